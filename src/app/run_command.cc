#include <app/command_options.h>
#include <compare/joint_name.h>
#include <output/analytic_report.h>
#include <output/comparison_report.h>
#include <output/fem_summary.h>
#include <output/figure_summary.h>
#include <output/floor_safety_lift.h>
#include <output/floor_safety_summary.h>
#include <output/gnuplot.h>
#include <output/governing_report.h>
#include <output/report_markdown.h>
#include <output/result_folder.h>
#include <output/run_summary.h>
#include <pipeline/closed_form_comparison.h>
#include <pipeline/fem_pipeline.h>
#include <scene/closed_forms.h>

#include <deal.II/base/timer.h>

#include <fmt/format.h>
#include <studies/accuracy_loop.h>

#include <iostream>
#include <optional>

namespace FloorBlock::App
{
  namespace
  {
    void
    write_plots(const Output::ResultFolder           &folder,
                const Output::RunComparison          &comparison,
                const Contact::SolveResult           &result,
                const Parameters::ScenarioParameters &scene)
    {
      const Contact::IncrementResult &last = result.increments.back();
      const std::string               governing =
        Output::governing_lift_plot(result,
                                    scene.geometry.n_blocks,
                                    scene.loading.floor_lift);
      if (!governing.empty())
        Output::render_png(governing, folder.path_of("stress_vs_lift.png"));
      const std::vector<Output::LiftSafety> along =
        Output::safety_along_lift(comparison.lift_history);
      if (!along.empty())
        Output::render_png(Output::safety_along_lift_plot(along),
                           folder.path_of("floor_safety_vs_lift.png"));
      const auto &final_joints = comparison.final_joints;
      Output::render_png(Output::force_per_joint_plot(final_joints),
                         folder.path_of("q_per_joint.png"));
      if (!comparison.lift_history.empty())
        Output::render_png(Output::lift_history_plot(comparison.lift_history),
                           folder.path_of("face_joint_vs_lift.png"),
                           1400,
                           550);
      for (const auto &joint : last.joints)
        if (joint.name == Compare::face_joint_name(final_joints.size()))
          Output::render_png(Output::traction_profile_plot(joint),
                             folder.path_of("face_joint_traction.png"),
                             700,
                             700);
    }

    void
    write_closed_forms(const Output::ResultFolder &folder,
                       const Scene::ClosedForms   &closed_forms)
    {
      folder.write_json("analytic.json", Output::analytic_json(closed_forms));
      folder.write("analytic.csv", Output::analytic_csv(closed_forms));
    }

    /// Compares, plots and reports the last converged increment.
    Output::RunComparison
    compare_and_report(const Pipeline::FemOutcome           &outcome,
                       const Scene::ClosedForms             &closed_forms,
                       const Parameters::ScenarioParameters &scene,
                       const Output::ResultFolder           &folder,
                       const std::optional<Output::FemErrorEstimate> &estimate)
    {
      const Output::RunComparison comparison =
        Pipeline::compare_with_closed_forms(outcome, closed_forms, scene);
      write_plots(folder, comparison, outcome.result, scene);
      const auto lines = Output::verdicts(comparison);
      for (const auto &line : lines)
        std::cout << "  " << line << "\n";
      const std::vector<Output::LiftSafety> along =
        Output::safety_along_lift(comparison.lift_history);
      if (!along.empty())
        std::cout << "  floor safety along the lift: "
                  << Output::unit_safety_text(along) << "\n";
      std::cout << Output::governing_lines(
        Compare::governing_joints(outcome.result.increments.back(),
                                  scene.geometry.n_blocks));
      folder.write(
        "report.md",
        Output::report_markdown(
          scene, outcome.result, outcome.report, estimate, comparison, lines,
          closed_forms));
      return comparison;
    }

    /// Which level is reported, and whether it met the accuracy target.
    void
    print_target(const std::optional<Output::FemErrorEstimate> &estimate)
    {
      if (!estimate || !estimate->target)
        return;
      const Output::AccuracyTarget &target = *estimate->target;
      const auto &reported = target.levels.at(target.reported_level);
      const bool  check =
        target.reported_solve == Output::ReportedSolve::refined;
      std::cout << fmt::format(
        "accuracy: target {:g} % {} after {} levels in {:.1f} "
        "s; reporting level {}{} ({} DoFs, FE degree {}): {}\n",
        100. * target.relative_error,
        target.met ? "met" : "NOT met",
        target.levels.size(),
        target.wall_time,
        target.reported_level,
        check ? "'s check" : "",
        check ? reported.halved_n_dofs : reported.n_dofs,
        target.fe_degree,
        target.stop_reason);
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
                  << folder.path_of("summary.json") << " in " << seconds << " s"
                  << std::endl;
      else
        std::cout << "wrote " << folder.path_of("report.md") << " and "
                  << folder.path_of("summary.json") << " in " << seconds << " s"
                  << std::endl;
    }
  } // namespace

  int
  run_command(const CommandOptions &options)
  {
    dealii::Timer timer;
    const auto    scene = read_scene(options);
    require_plane_scene(scene, "run");
    const Output::ResultFolder folder(output_directory(options, scene));
    folder.mark_unfinished();
    folder.write_inputs(scene);

    const auto closed_forms = Scene::evaluate_closed_forms(scene);
    write_closed_forms(folder, closed_forms);
    const Studies::TargetedSolve solve =
      Studies::solve_to_target(scene, folder);
    const Pipeline::FemOutcome &outcome  = solve.outcome;
    const auto                 &estimate = solve.estimate;
    print_target(estimate);
    std::cout << Output::fem_summary_text(outcome.report,
                                          outcome.result,
                                          outcome.mesh);
    std::optional<Output::RunComparison> comparison;
    if (!outcome.result.increments.empty())
      {
        std::cout << "face joint: each figure with its estimated error and "
                     "the time of the solve that gave it\n"
                  << Output::figure_lines(outcome.result,
                                          estimate,
                                          scene.geometry.n_blocks)
                  << Output::floor_safety_summary_lines(
                       outcome.report.corner_safety, estimate, closed_forms);
        comparison =
          compare_and_report(outcome, closed_forms, scene, folder, estimate);
      }

    // Written last: its presence marks a finished run.
    folder.write_summary(Output::run_summary_json(scene,
                                                  closed_forms,
                                                  outcome.result,
                                                  outcome.report,
                                                  estimate,
                                                  comparison,
                                                  timer.wall_time()));
    print_written(outcome, folder, timer.wall_time());
    return outcome.converged ? exit_code::success : exit_code::failure;
  }
} // namespace FloorBlock::App
