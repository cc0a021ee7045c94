#include <compare/joint_comparison.h>
#include <pipeline/closed_form_comparison.h>

namespace FloorBlock::Pipeline
{
  Output::RunComparison
  compare_with_closed_forms(const FemOutcome                     &outcome,
                            const Scene::ClosedForms             &closed_forms,
                            const Parameters::ScenarioParameters &scene)
  {
    Output::RunComparison comparison;
    comparison.inputs    = Compare::closed_form_inputs(closed_forms);
    comparison.constants = {scene.material.youngs_modulus(),
                            scene.geometry.support_width,
                            scene.geometry.block_width,
                            scene.geometry.block_height};
    comparison.final_joints =
      Compare::compare_vertical_joints(outcome.result.increments.back(),
                                       closed_forms,
                                       comparison.constants);
    for (const auto &increment : outcome.result.increments)
      if (increment.stage == Loading::LoadStage::uplift)
        comparison.lift_history.push_back(
          {increment.stage_factor * scene.loading.floor_lift,
           Compare::compare_vertical_joints(increment,
                                            closed_forms,
                                            comparison.constants)
             .back()});
    return comparison;
  }
} // namespace FloorBlock::Pipeline
