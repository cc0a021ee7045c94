#include <app/command_options.h>
#include <common/input_error.h>
#include <common/wall_clock.h>
#include <output/gnuplot.h>
#include <output/result_folder.h>

#include <deal.II/base/mpi.h>

#include <assessment/assessment.h>
#include <assessment/assessment_files.h>
#include <assessment/assessment_plots.h>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace FloorBlock::App
{
  namespace
  {
    /** Folder of the FEM case records under the results. */
    const std::string case_folder_name = "assess_cases";

    /**
     * The scene as the cases solve it, less subsection Uncertainty: what
     * is drawn there each case record holds itself (solve_safety_cases
     * recomputes a record of other inputs), and the rest (budget, targets)
     * changes no case.
     */
    std::string
    case_scene_text(const Parameters::ScenarioParameters &scene)
    {
      std::istringstream lines(scene.expanded_text);
      std::string        line, text;
      unsigned int       depth = 0, uncertainty_depth = 0;
      while (std::getline(lines, line))
        {
          const auto        first = line.find_first_not_of(' ');
          const std::string trimmed =
            first == std::string::npos ? "" : line.substr(first);
          if (trimmed.rfind("subsection ", 0) == 0)
            {
              ++depth;
              if (uncertainty_depth == 0 && trimmed == "subsection Uncertainty")
                uncertainty_depth = depth;
            }
          const bool inside = uncertainty_depth > 0;
          if (trimmed == "end")
            {
              if (depth == uncertainty_depth)
                uncertainty_depth = 0;
              --depth;
            }
          if (!inside)
            text += line + "\n";
        }
      return text;
    }

    /**
     * Refuses a results folder whose case records were solved for another
     * scene (checked before anything is written); the records of the same
     * scene are reused.
     */
    void
    check_case_folder(const std::string &folder, const std::string &scene_text)
    {
      const std::filesystem::path path =
        std::filesystem::path(folder) / case_folder_name / "scene.prm";
      if (!std::filesystem::exists(path))
        return;
      std::ifstream      file(path);
      std::ostringstream stored;
      stored << file.rdbuf();
      if (stored.str() != scene_text)
        throw InputError(
          "--output",
          folder,
          "a folder without FEM cases of another scene: " + path.string() +
            " records other scene parameters than this "
            "run's; remove " +
            (std::filesystem::path(folder) / case_folder_name).string() +
            " or choose another --output");
    }

    void
    print_result(const Assessment::AssessmentResult &result,
                 const Output::ResultFolder         &folder)
    {
      const auto &mc = result.failure.monte_carlo;
      std::cout << fmt::format(
        "P(FS < 1) = {:.4f} +- {:.4f} (95 %, {} surrogate evaluations); "
        "{:.4f} to {:.4f} if the surrogate's FS errs by its stated factor "
        "{:.3f}\n",
        mc.probability,
        mc.half_width,
        mc.evaluations,
        result.failure.lower_with_surrogate_error,
        result.failure.upper_with_surrogate_error,
        std::exp(result.surrogate.stated_error));
      std::cout << fmt::format("FORM: beta = {:.3f}, P = {:.4f}\n",
                               result.design_point.reliability_index,
                               result.design_point.probability);
      std::cout << "Sobol' indices (first order / total):\n";
      for (std::size_t i = 0; i < result.inputs.size(); ++i)
        std::cout << fmt::format("  {:<40} {:.3f} / {:.3f}\n",
                                 result.inputs[i].path,
                                 result.sobol.first_order[i],
                                 result.sobol.total_order[i]);
      std::cout << fmt::format(
        "surrogate of ln FS: {}; stated error {:.1f} % of FS (95 % of new "
        "cases within, from cross validation), held-out rms {:.1f} % over {} "
        "FEM cases, {:.0f} % of them within the stated error\n",
        result.surrogate.kind,
        100. * std::expm1(result.surrogate.stated_error),
        100. * std::expm1(result.held_out.rms),
        result.held_out.n_points,
        100. * result.held_out.share_within_stated);
      if (result.design_limit)
        for (const auto &[target, value] : result.design_limit->limits)
          std::cout << fmt::format(
            "design limit: P(FS < 1) = {:g} {}\n",
            target,
            value ?
              fmt::format("at {} = {:.4g} {}",
                          result.inputs[result.design_limit->input].path,
                          *value,
                          result.inputs[result.design_limit->input].unit) :
              fmt::format("is not reached between the 1 % and 99 % "
                          "quantiles of {}",
                          result.inputs[result.design_limit->input].path));
      for (const auto &cost : result.costs)
        std::cout << fmt::format("cost: {} {} evaluations ({} from an "
                                 "earlier run), {:.1f} s\n",
                                 cost.model,
                                 cost.evaluations,
                                 cost.from_earlier_runs,
                                 cost.wall_time);
      std::cout << "wrote " << folder.path_of("assess.json") << ", "
                << folder.path_of("cases.csv") << ", "
                << folder.path_of("assess_fs.png") << ", "
                << folder.path_of("assess_sobol.png") << ", "
                << folder.path_of("assess_fs_inputs.png") << std::endl;
    }
  } // namespace

  int
  assess_command(const CommandOptions &options)
  {
    const auto scene = read_scene(options);
    require_plane_scene(scene, "assess");
    if (scene.model.chosen != Parameters::BlockModel::elastic)
      throw InputError("Model/Blocks",
                       "rigid",
                       "elastic (or auto) for `assess`: the safety factor "
                       "reads the stress at the floor corners, which rigid "
                       "blocks do not have");
    Assessment::checked_input_distribution(scene);
    const std::string output     = output_directory(options, scene);
    const std::string scene_text = case_scene_text(scene);
    check_case_folder(output, scene_text);

    const bool first_process =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const Output::ResultFolder folder(output, first_process);
    folder.write_inputs(scene);
    folder.write(case_folder_name + "/scene.prm", scene_text);

    const ScopedSolveDeadline        deadline(scene.uncertainty.time_budget);
    Assessment::AssessmentResult     result;
    Assessment::AssessmentIncomplete incomplete;
    const bool                       complete = Assessment::run_assessment(
      scene,
      {options.scene_path, options.overrides, scene.uncertainty.inputs},
      folder.path_of(case_folder_name),
      std::cout,
      result,
      incomplete);
    if (!complete)
      {
        if (first_process)
          std::cerr << fmt::format(
            "floorblock: assess stopped at Uncertainty/Time budget = {} s "
            "with {} of {} FEM cases done, kept in {}; run the same command "
            "again to resume from them\n",
            scene.uncertainty.time_budget,
            incomplete.n_cases_done,
            incomplete.n_cases_total,
            folder.path_of(case_folder_name));
        return exit_code::failure;
      }
    if (first_process)
      {
        folder.write("cases.csv", Assessment::cases_csv(result));
        folder.write_json("assess.json", Assessment::assessment_json(result));
        Output::render_png(Assessment::safety_factor_distribution_plot(result),
                           folder.path_of("assess_fs.png"),
                           1400,
                           550);
        Output::render_png(Assessment::sobol_indices_plot(result),
                           folder.path_of("assess_sobol.png"),
                           1000,
                           600);
        Output::render_png(Assessment::safety_factor_inputs_plot(result),
                           folder.path_of("assess_fs_inputs.png"),
                           1400,
                           550);
        if (result.design_limit)
          {
            folder.write("design_limit.csv",
                         Assessment::design_limit_csv(result));
            Output::render_png(Assessment::design_limit_plot(result),
                               folder.path_of("assess_design_limit.png"),
                               1000,
                               600);
          }
        print_result(result, folder);
      }
    return exit_code::success;
  }
} // namespace FloorBlock::App
