#include <app/command_options.h>
#include <pipeline/error_estimate.h>
#include <pipeline/fem_pipeline.h>
#include <compare/joint_comparison.h>
#include <output/analytic_report.h>
#include <output/comparison_report.h>
#include <output/fem_report.h>
#include <output/figure_summary.h>
#include <output/gnuplot.h>
#include <output/report_markdown.h>
#include <output/result_folder.h>
#include <scene/closed_forms.h>

#include <deal.II/base/timer.h>

#include <iostream>
#include <optional>

namespace FloorBlock::App
{
  using nlohmann::json;

  namespace
  {
    Compare::ContactConstants
    contact_constants(const Parameters::ScenarioParameters &scene)
    {
      return {scene.material.youngs_modulus(), scene.geometry.support_width,
              scene.geometry.block_width, scene.geometry.block_height};
    }

    /// Face-joint comparison at every converged uplift increment.
    json
    lift_history(const Pipeline::FemOutcome &          outcome,
                 const Scene::ClosedForms &            closed_forms,
                 const Parameters::ScenarioParameters &scene)
    {
      json history = json::array();
      for (const auto &increment : outcome.result.increments)
        if (increment.stage == Contact::LoadStage::uplift)
          {
            const auto joints = Compare::compare_vertical_joints(
              increment, closed_forms, contact_constants(scene));
            history.push_back(Output::lift_history_entry(
              joints.back(), contact_constants(scene),
              increment.stage_factor * scene.loading.floor_lift));
          }
      return history;
    }

    void
    write_plots(const Output::ResultFolder &                 folder,
                const std::vector<Compare::JointComparison> &final_joints,
                const json &                                 history,
                const Contact::IncrementResult &             last)
    {
      Output::render_png(Output::force_per_joint_plot(final_joints),
                         folder.path_of("q_per_joint.png"));
      if (!history.empty())
        Output::render_png(Output::lift_history_plot(history),
                           folder.path_of("face_joint_vs_lift.png"), 1400, 550);
      for (const auto &joint : last.joints)
        if (joint.name == "vertical " + std::to_string(final_joints.size()))
          Output::render_png(Output::traction_profile_plot(joint),
                             folder.path_of("face_joint_traction.png"), 700,
                             700);
    }
  
    json
    write_closed_forms(const Output::ResultFolder &folder,
                       const Scene::ClosedForms &  closed_forms)
    {
      const json analytic = Output::analytic_json(closed_forms);
      folder.write_json("analytic.json", analytic);
      folder.write("analytic.csv", Output::analytic_csv(closed_forms));
      return analytic;
    }

    /// Compares, plots and reports the last converged increment.
    void
    compare_and_report(const Pipeline::FemOutcome &          outcome,
                       const Scene::ClosedForms &            closed_forms,
                       const Parameters::ScenarioParameters &scene,
                       const Output::ResultFolder &          folder,
                       const std::optional<Output::FemErrorEstimate> &estimate,
                       json &                                summary)
    {
      const auto &last         = outcome.result.increments.back();
      const auto  final_joints = Compare::compare_vertical_joints(
        last, closed_forms, contact_constants(scene));
      const json history = lift_history(outcome, closed_forms, scene);
      summary["comparison"] = {
        {"final", Output::comparison_json(final_joints,
                                          contact_constants(scene),
                                          scene.geometry.n_blocks)},
        {"lift_history", history}};
      write_plots(folder, final_joints, history, last);
      const auto lines = Output::verdicts(final_joints.back());
      for (const auto &line : lines)
        std::cout << "  " << line << "\n";
      folder.write("report.md",
                   Output::report_markdown(scene, outcome.result,
                                           outcome.report, estimate, summary,
                                           lines));
    }

    /// The closing line: what was written, and in how long.
    void
    print_written(const Pipeline::FemOutcome &outcome,
                  const Output::ResultFolder &folder,
                  const double                seconds)
    {
      if (outcome.result.increments.empty())
        std::cout << "no load increment converged: no comparison and no "
                     "report.md; wrote "
                  << folder.path_of("summary.json") << " in " << seconds
                  << " s" << std::endl;
      else
        std::cout << "wrote " << folder.path_of("report.md") << " and "
                  << folder.path_of("summary.json") << " in " << seconds
                  << " s" << std::endl;
    }
  } // namespace

  int
  run_command(const CommandOptions &options)
  {
    dealii::Timer timer;
    const auto    scene = read_scene(options);
    const Output::ResultFolder folder(output_directory(options, scene));
    folder.mark_unfinished();
    folder.write_inputs(scene);

    const auto closed_forms = Scene::evaluate_closed_forms(scene);
    const json analytic     = write_closed_forms(folder, closed_forms);
    const Pipeline::FemOutcome outcome = Pipeline::solve_scene(scene, folder);
    std::cout << Pipeline::fem_summary_text(outcome);
    json summary = {{"scene", scene.scene_name},
                    {"model", outcome.report.model},
                    {"inputs", scene.expanded_text},
                    {"analytic", analytic},
                    {"fem", Output::fem_json(outcome.result, outcome.report)}};
    const auto estimate = Pipeline::estimate_error(scene, outcome, folder);
    if (estimate)
      summary["fem_error_estimate"] = Output::fem_error_estimate_json(*estimate);
    if (!outcome.result.increments.empty())
      {
        summary["face_joint_figures"] = Output::face_joint_figures(
          outcome.result, estimate, scene.geometry.n_blocks);
        std::cout << "face joint: each figure with its estimated error and "
                     "the time of the solve that gave it\n"
                  << Output::figure_lines(summary["face_joint_figures"]);
        compare_and_report(outcome, closed_forms, scene, folder, estimate,
                           summary);
      }

    // Written last: its presence marks a finished run.
    summary["status"]      = outcome.report.status;
    summary["status_text"] = outcome.report.status_text;
    summary["wall_time_s"] = timer.wall_time();
    folder.write_summary(summary);
    print_written(outcome, folder, timer.wall_time());
    return outcome.converged ? exit_code::success : exit_code::failure;
  }
} // namespace FloorBlock::App
