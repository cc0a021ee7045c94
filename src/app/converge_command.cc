#include <app/command_options.h>
#include <convergence/equal_error.h>
#include <output/convergence_report.h>
#include <output/gnuplot.h>
#include <output/result_folder.h>
#include <pipeline/convergence_ladder.h>
#include <pipeline/convergence_study.h>
#include <scene/rigid_inputs.h>

#include <deal.II/base/timer.h>

#include <fmt/format.h>

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
    using Convergence::Ladder;
    using Convergence::Quantity;

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

    /// Partial results after every level; the final JSON adds the comparison.
    void
    write_tables(const Output::ResultFolder  &folder,
                 const std::vector<Ladder>   &ladders,
                 const std::vector<Quantity> &quantities)
    {
      folder.write("convergence.csv",
                   Output::convergence_csv(ladders, quantities));
      folder.write_json("convergence.json",
                        Output::convergence_json(ladders, quantities, {}));
    }


    /** Runs each ladder, writing the tables after every level. */
    bool
    run_ladders(const CommandOptions                 &options,
                const Parameters::ScenarioParameters &scene,
                const std::vector<Quantity>          &quantities,
                const Output::ResultFolder           &folder,
                const dealii::Timer                  &command_timer,
                std::vector<Ladder>                  &ladders)
    {
      Convergence::RefinementSettings refinement;
      refinement.bulk_fraction                      = options.bulk_fraction;
      refinement.traction_jump_fraction             = options.jump_fraction;
      bool                            all_converged = true;
      const std::vector<unsigned int> degrees =
        options.fe_degrees.empty() ?
          std::vector<unsigned int>{scene.solver.fe_degree} :
          options.fe_degrees;
      for (const unsigned int degree : degrees)
        {
          Parameters::ScenarioParameters degree_scene = scene;
          degree_scene.solver.fe_degree               = degree;
          for (const Pipeline::RefinementMode mode :
               Pipeline::refinement_modes(options.refinement_mode))
            {
              ladders.push_back(
                {Pipeline::ladder_name(mode, degree), {}, {}, {}});
              // One budget for the whole command: each ladder gets what the
              // ladders before it left.
              Convergence::LadderBudget budget;
              budget.seconds =
                budget_seconds(options) - command_timer.wall_time();
              budget.max_dofs = options.max_dofs;
              const auto run  = Pipeline::run_ladder(
                degree_scene,
                mode,
                n_levels(options),
                refinement,
                options.coarsen_fraction,
                folder,
                [&](const std::vector<Convergence::LevelRecord> &so_far) {
                  ladders.back().levels = so_far;
                  Convergence::estimate_ladder_errors(ladders.back(),
                                                      quantities);
                  write_tables(folder, ladders, quantities);
                },
                budget);
              ladders.back().stopped_because = run.stopped_because;
              for (const auto &record : run.levels)
                all_converged = all_converged && record.converged();
              std::cout << Output::ladder_text(ladders.back(), quantities);
            }
        }
      return all_converged;
    }

    /** convergence.json with the verdicts, and the error-time plot. */
    Output::TargetVerdict
    write_study(const CommandOptions                 &options,
                const Parameters::ScenarioParameters &scene,
                const std::vector<Ladder>            &ladders,
                const std::vector<Quantity>          &quantities,
                const Output::ResultFolder           &folder)
    {
      const auto comparisons =
        Pipeline::equal_error_comparisons(ladders,
                                          quantities,
                                          options.target_error);
      const Output::TargetVerdict verdict =
        Pipeline::target_verdict(comparisons, "adaptive");
      folder.write_json("convergence.json",
                        Output::convergence_study_json(
                          ladders,
                          quantities,
                          comparisons,
                          verdict,
                          options.refinement_mode == "all" ?
                            std::optional(
                              Pipeline::target_verdict(comparisons, "remesh")) :
                            std::nullopt));
      Output::render_png(
        Output::error_vs_time_plot(ladders,
                                   quantities,
                                   scene.scene_name +
                                     ": error estimate against wall time"),
        folder.path_of("error_vs_wall_time.png"),
        1300,
        700);
      std::cout << "adaptive target (<= " << Pipeline::target_dofs_ratio
                << " of the DoFs and less time at "
                << options.target_error * 100
                << " % error): " << verdict.status() << ". " << verdict.text
                << std::endl;
      const std::string degrees = Pipeline::degree_comparison_text(comparisons);
      if (!degrees.empty())
        std::cout << "FE degrees at " << options.target_error * 100
                  << " % error: " << degrees << std::endl;
      return verdict;
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

    const auto quantities =
      Convergence::quantities_of_interest(scene.geometry.n_blocks);
    std::vector<Ladder> ladders;
    const bool          all_converged =
      run_ladders(options, scene, quantities, folder, timer, ladders);
    const Output::TargetVerdict verdict =
      write_study(options, scene, ladders, quantities, folder);

    // Written last: its presence marks a finished study.
    folder.write_summary(Output::convergence_summary_json(
      scene.scene_name, all_converged, verdict, timer.wall_time()));
    std::cout << "wrote " << folder.path_of("convergence.csv") << ", "
              << folder.path_of("convergence.json") << ", "
              << folder.path_of("error_vs_wall_time.png") << " in "
              << fmt::format("{:.1f}", timer.wall_time()) << " s" << std::endl;
    return all_converged ? exit_code::success : exit_code::failure;
  }
} // namespace FloorBlock::App
