#include <app/command_options.h>
#include <assessment/assessment.h>
#include <assessment/assessment_files.h>
#include <common/input_error.h>
#include <common/wall_clock.h>
#include <output/result_folder.h>

#include <deal.II/base/mpi.h>

#include <fmt/format.h>

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
     * The scene as the cases solve it, less the budgets (which change no
     * result): a rerun into the same folder must solve the same scene to
     * reuse its records.
     */
    std::string
    case_scene_text(const Parameters::ScenarioParameters &scene)
    {
      std::istringstream lines(scene.expanded_text);
      std::string        line, text;
      while (std::getline(lines, line))
        if (line.find("set Time budget") == std::string::npos)
          text += line + "\n";
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
        throw InputError("--output",
                         folder,
                         "a folder without FEM cases of another scene: " +
                           path.string() +
                           " records other scene parameters than this "
                           "run's; remove " +
                           (std::filesystem::path(folder) / case_folder_name)
                             .string() +
                           " or choose another --output");
    }

    void
    print_result(const Assessment::AssessmentResult &result,
                 const Output::ResultFolder         &folder)
    {
      const auto &mc = result.failure.monte_carlo;
      std::cout << fmt::format(
        "P(FS < 1) = {:.4f} +- {:.4f} (95 %, {} surrogate evaluations); "
        "{:.4f} to {:.4f} if the surrogate errs by its stated {:.3f}\n",
        mc.probability,
        mc.half_width,
        mc.evaluations,
        result.failure.lower_with_surrogate_error,
        result.failure.upper_with_surrogate_error,
        result.surrogate.stated_error);
      std::cout << fmt::format(
        "FORM: beta = {:.3f}, P = {:.4f}\n",
        result.design_point.reliability_index,
        result.design_point.probability);
      std::cout << "Sobol' indices (first order / total):\n";
      for (std::size_t i = 0; i < result.inputs.size(); ++i)
        std::cout << fmt::format("  {:<40} {:.3f} / {:.3f}\n",
                                 result.inputs[i].path,
                                 result.sobol.first_order[i],
                                 result.sobol.total_order[i]);
      std::cout << fmt::format(
        "surrogate: polynomial chaos of degree {}, {} terms; stated error "
        "{:.4f} (cross-validated), held-out rms {:.4f} over {} FEM cases, "
        "{:.0f} % within the stated error\n",
        result.surrogate.degree,
        result.surrogate.n_terms,
        result.surrogate.stated_error,
        result.held_out.rms,
        result.held_out.n_points,
        100. * result.held_out.share_within_stated);
      for (const auto &cost : result.costs)
        std::cout << fmt::format("cost: {} {} evaluations ({} from an "
                                 "earlier run), {:.1f} s\n",
                                 cost.model,
                                 cost.evaluations,
                                 cost.from_earlier_runs,
                                 cost.wall_time);
      std::cout << "wrote " << folder.path_of("assess.json") << ", "
                << folder.path_of("cases.csv") << std::endl;
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

    const ScopedSolveDeadline deadline(scene.uncertainty.time_budget);
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
        print_result(result, folder);
      }
    return exit_code::success;
  }
} // namespace FloorBlock::App
