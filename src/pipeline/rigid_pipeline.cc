#include <pipeline/fem_report_builder.h>
#include <pipeline/rigid_pipeline.h>
#include <rigid/contact_adapter.h>
#include <rigid/model.h>
#include <scene/rigid_inputs.h>

#include <string>

namespace FloorBlock::Pipeline
{
  namespace
  {
    std::string
    failure_text(const RigidBlocks::RigidSolveResult &result)
    {
      std::string text =
        RigidBlocks::to_string(result.status) + ": " + result.message;
      if (result.failing_block > 0)
        text += " (block " + std::to_string(result.failing_block) + ")";
      for (const std::string &attempt : result.failed_attempts)
        text += "; tried: " + attempt;
      return text;
    }
  } // namespace

  FemOutcome
  solve_rigid_scene(const Parameters::ScenarioParameters &scene,
                    const Output::ResultFolder           &folder)
  {
    const RigidBlocks::Model model(Scene::rigid_model_description(scene));
    const RigidBlocks::RigidSolveResult rigid = model.solve();

    FemOutcome outcome;
    outcome.converged = rigid.status == RigidBlocks::SolveStatus::converged;
    outcome.result =
      RigidBlocks::to_contact_result(rigid,
                                     model,
                                     scene.solver.averaging_length);
    outcome.report =
      make_fem_report(outcome.result,
                      scene,
                      "rigid blocks",
                      outcome.converged,
                      outcome.converged ? "every loading increment converged" :
                                          failure_text(rigid));
    outcome.report.rigid =
      Output::RigidModelNote{RigidBlocks::to_string(rigid.status),
                             scene.model.rigid_points_per_joint,
                             scene.geometry.corner_rounding_radius};
    write_fem_files(outcome, folder);
    return outcome;
  }
} // namespace FloorBlock::Pipeline
