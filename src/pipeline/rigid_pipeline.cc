#include <pipeline/rigid_pipeline.h>
#include <rigid/contact_adapter.h>
#include <rigid/model.h>
#include <scene/rigid_inputs.h>

#include <string>

namespace FloorBlock::Pipeline
{
  using nlohmann::json;

  namespace
  {
    std::string
    failure_text(const RigidBlocks::SolveResult &result)
    {
      std::string text = RigidBlocks::to_string(result.status) + ": " +
                         result.message;
      if (result.failing_block > 0)
        text += " (block " + std::to_string(result.failing_block) + ")";
      for (const std::string &attempt : result.failed_attempts)
        text += "; tried: " + attempt;
      return text;
    }

    /** What the rigid model is, and what it does not produce. */
    void
    describe_rigid_model(const Parameters::ScenarioParameters &scene,
                         const RigidBlocks::SolveResult &      rigid,
                         json &                                fem)
    {
      fem["model"]        = "rigid blocks";
      fem["model_choice"] = scene.model.choice_reason;
      fem["rigid_status"] = RigidBlocks::to_string(rigid.status);
      fem["dofs"] = "3 per block: centroid translation x, y and rotation";
      fem["points_per_joint"] = scene.model.rigid_points_per_joint;
      fem["tractions"] =
        "joint springs on rigid blocks: t_n = kn x overlap at each "
        "integration point (the Winkler reading of Eq. 6.51)";
      fem["force_balance_definition"] =
        "largest force or moment (over L) imbalance of a single block, from "
        "the joint resultants and the loads, over the larger of the total "
        "load and the largest joint resultant";
      fem["n_contact_pairs"] = nullptr;
      fem["mesh"]            = nullptr;
      fem["absent"] = {
        {"mesh", "rigid blocks need no mesh"},
        {"vtu", "no field to write: the blocks move rigidly"},
        {"n_contact_pairs", "joints are integrated at points, not paired "
                            "nodes"}};
      if (scene.geometry.corner_rounding_radius > 0.)
        fem["geometry_note"] =
          "Geometry/Corner rounding radius = " +
          std::to_string(scene.geometry.corner_rounding_radius) +
          " m is ignored: the rigid blocks have sharp corners";
    }
  } // namespace

  FemOutcome
  solve_rigid_scene(const Parameters::ScenarioParameters &scene,
                    const Output::ResultFolder &          folder)
  {
    const RigidBlocks::Model model(Scene::rigid_model_description(scene));
    const RigidBlocks::SolveResult rigid = model.solve();

    FemOutcome outcome;
    outcome.converged = rigid.status == RigidBlocks::SolveStatus::converged;
    outcome.result    = RigidBlocks::to_contact_result(
      rigid, model, scene.solver.averaging_length);
    const Output::FemReportContext context{
      scene.geometry.n_blocks,
      scene.geometry.support_width,
      outcome.converged ? "converged" : "not converged",
      outcome.converged ? "every loading increment converged" :
                          failure_text(rigid),
      scene.material.youngs_modulus()};
    outcome.fem = Output::fem_json(outcome.result, context);
    describe_rigid_model(scene, rigid, outcome.fem);
    folder.write_json("fem.json", outcome.fem);
    folder.write("joints.csv", Output::joints_csv(outcome.result, context));
    return outcome;
  }
} // namespace FloorBlock::Pipeline
