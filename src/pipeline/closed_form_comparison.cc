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
    // The joint forces of an increment that carries no load are round-off,
    // and so would be their ratios to the friction limits.
    if (comparison.final_joints.empty() ||
        comparison.final_joints.back().load.carries_load())
      comparison.joint_states =
        Compare::joint_states(outcome.result.increments.back(), closed_forms);
    else
      comparison.joint_states.text =
        "not evaluated: the FEM's forces are round-off (no load)";
    for (const auto &increment : outcome.result.increments)
      if (increment.stage == Loading::LoadStage::uplift)
        comparison.lift_history.push_back(
          {increment.stage_factor * scene.loading.floor_lift,
           Compare::compare_vertical_joints(increment,
                                            closed_forms,
                                            comparison.constants)
             .back(),
           increment.corner_factors});
    return comparison;
  }
} // namespace FloorBlock::Pipeline
