#include <output/analytic_report.h>
#include <output/figure_summary.h>
#include <output/floor_safety_lift.h>
#include <output/floor_safety_summary.h>
#include <output/governing_report.h>
#include <output/run_summary.h>

namespace FloorBlock::Output
{
  using nlohmann::json;

  json
  run_summary_json(const Parameters::ScenarioParameters  &scene,
                   const Scene::ClosedForms              &closed_forms,
                   const Contact::SolveResult            &result,
                   const FemReport                       &report,
                   const std::optional<FemErrorEstimate> &estimate,
                   const std::optional<RunComparison>    &comparison,
                   const double                           wall_time)
  {
    json summary = {{"scene", scene.scene_name},
                    {"model", report.model},
                    {"inputs", scene.expanded_text},
                    {"analytic", analytic_json(closed_forms)},
                    {"fem", fem_json(result, report)},
                    {"status", report.status},
                    {"status_text", report.status_text},
                    {"wall_time_s", wall_time}};
    if (estimate)
      summary["fem_error_estimate"] = fem_error_estimate_json(*estimate);
    if (!result.increments.empty())
      {
        summary["face_joint_figures"] =
          face_joint_figures(result, estimate, scene.geometry.n_blocks);
        summary["governing_joints"] =
          governing_json(Compare::governing_joints(result.increments.back(),
                                                   scene.geometry.n_blocks));
      }
    summary["floor_safety"] =
      floor_safety_summary_json(report.corner_safety, estimate, closed_forms);
    if (comparison && !comparison->lift_history.empty())
      summary["floor_safety"]["along_lift"] = safety_along_lift_json(
        safety_along_lift(comparison->lift_history));
    if (comparison)
      summary["comparison"] =
        run_comparison_json(*comparison, scene.geometry.n_blocks);
    return summary;
  }
} // namespace FloorBlock::Output
