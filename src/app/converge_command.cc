#include <app/command_options.h>
#include <output/convergence_report.h>
#include <output/gnuplot.h>
#include <output/result_folder.h>
#include <scene/rigid_inputs.h>

#include <deal.II/base/timer.h>

#include <fmt/format.h>
#include <refinement/equal_error.h>
#include <studies/convergence_ladder.h>
#include <studies/convergence_study.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>

namespace FloorBlock::App
{
  namespace
  {
    using Refinement::Ladder;
    using Refinement::Quantity;

    constexpr unsigned int max_levels = 10;
    /** Levels without --levels: at most this many, within
     * default_budget_seconds. */
    constexpr unsigned int default_levels = 5;
    /** Wall time of a study without --levels or --budget-seconds (s). */
    constexpr double default_budget_seconds = 60.;

    /** --levels, or default_levels. */
    unsigned int
    n_levels(const CommandOptions &options)
    {
      return options.n_levels == 0 ? default_levels : options.n_levels;
    }

    /**
     * --budget-seconds; else none if the user asked for a number of levels
     * (that is the budget), else default_budget_seconds.
     */
    double
    budget_seconds(const CommandOptions &options)
    {
      if (!std::isnan(options.budget_seconds))
        return options.budget_seconds;
      return options.n_levels == 0 ? default_budget_seconds :
                                     std::numeric_limits<double>::infinity();
    }

    void
    check_options(const CommandOptions &options)
    {
      if (options.n_levels != 0 &&
          (options.n_levels < 2 || options.n_levels > max_levels))
        throw InputError("--levels",
                         std::to_string(options.n_levels),
                         "2 to " + std::to_string(max_levels) +
                           " (Richardson extrapolation needs 3)");
      for (const auto &[name, value] :
           {std::pair<std::string, double>{"--bulk-fraction",
                                           options.bulk_fraction},
            {"--jump-fraction", options.jump_fraction},
            {"--target-error", options.target_error}})
        if (!(value > 0. && value <= 1.))
          throw InputError(name, fmt::format("{}", value), "0 < value <= 1");
      if (!std::isnan(options.budget_seconds) && !(options.budget_seconds > 0.))
        throw InputError("--budget-seconds",
                         fmt::format("{}", options.budget_seconds),
                         "a wall time > 0 s");
      for (std::size_t k = 0; k < options.fe_degrees.size(); ++k)
        {
          const unsigned int degree = options.fe_degrees[k];
          if (degree < 1 || degree > 2)
            throw InputError("--degrees",
                             std::to_string(degree),
                             "FE degrees 1 and 2");
          if (std::count(options.fe_degrees.begin(),
                         options.fe_degrees.begin() + k,
                         degree) > 0)
            throw InputError("--degrees",
                             std::to_string(degree),
                             "each degree once");
        }
      if (options.max_dofs < 1000)
        throw InputError("--max-dofs",
                         std::to_string(options.max_dofs),
                         "at least 1000");
      if (!(options.coarsen_fraction >= 0. && options.coarsen_fraction < 1.))
        throw InputError("--coarsen-fraction",
                         fmt::format("{}", options.coarsen_fraction),
                         "0 <= value < 1");
    }

    std::string
    convergence_folder(const CommandOptions                 &options,
                       const Parameters::ScenarioParameters &scene)
    {
      if (!options.output_directory.empty())
        return options.output_directory;
      return (std::filesystem::path("results") / scene.scene_name /
              "convergence")
        .string();
    }

    Studies::StudySettings
    study_settings(const CommandOptions &options)
    {
      Studies::StudySettings settings;
      settings.fe_degrees                        = options.fe_degrees;
      settings.refinement_mode                   = options.refinement_mode;
      settings.n_levels                          = n_levels(options);
      settings.budget_seconds                    = budget_seconds(options);
      settings.max_dofs                          = options.max_dofs;
      settings.refinement.bulk_fraction          = options.bulk_fraction;
      settings.refinement.traction_jump_fraction = options.jump_fraction;
      settings.coarsen_fraction                  = options.coarsen_fraction;
      settings.target_error                      = options.target_error;
      return settings;
    }

    /** The verdicts on the adaptive target and on the FE degrees. */
    void
    print_verdicts(const Studies::ConvergenceStudy &study,
                   const double                     target_error)
    {
      std::cout << "adaptive target (<= " << Studies::target_dofs_ratio
                << " of the DoFs and less time at " << target_error * 100
                << " % error): " << study.adaptive_target.status() << ". "
                << study.adaptive_target.text << std::endl;
      const std::string degrees =
        Studies::degree_comparison_text(study.comparisons);
      if (!degrees.empty())
        std::cout << "FE degrees at " << target_error * 100
                  << " % error: " << degrees << std::endl;
    }
  } // namespace

  int
  converge_command(const CommandOptions &options)
  {
    dealii::Timer timer;
    check_options(options);
    const auto scene = read_scene(options);
    require_plane_scene(scene, "converge");
    // The ladder refines the elastic FEM's mesh; rigid blocks have none, and
    // every level would repeat the same rigid answer.
    if (Scene::uses_rigid_blocks(scene))
      throw InputError(
        "Model/Blocks",
        "rigid (or auto choosing rigid)",
        "converge needs the elastic FEM: Model/Blocks = elastic");
    const Output::ResultFolder folder(convergence_folder(options, scene));
    folder.mark_unfinished();
    folder.write_inputs(scene);

    const Studies::ConvergenceStudy study = Studies::run_convergence_study(
      scene,
      study_settings(options),
      folder,
      [](const Refinement::Ladder                &ladder,
         const std::vector<Refinement::Quantity> &quantities) {
        std::cout << Output::ladder_text(ladder, quantities);
      });
    print_verdicts(study, options.target_error);

    // Written last: its presence marks a finished study.
    folder.write_summary(Output::convergence_summary_json(scene.scene_name,
                                                          study.all_converged,
                                                          study.adaptive_target,
                                                          timer.wall_time()));
    std::cout << "wrote " << folder.path_of("convergence.csv") << ", "
              << folder.path_of("convergence.json") << ", "
              << folder.path_of("error_vs_wall_time.png") << " in "
              << fmt::format("{:.1f}", timer.wall_time()) << " s" << std::endl;
    return study.all_converged ? exit_code::success : exit_code::failure;
  }
} // namespace FloorBlock::App
