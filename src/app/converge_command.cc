#include <app/command_options.h>
#include <pipeline/convergence_ladder.h>
#include <convergence/equal_error.h>
#include <output/convergence_report.h>
#include <output/gnuplot.h>
#include <output/result_folder.h>
#include <scene/rigid_inputs.h>

#include <deal.II/base/timer.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace FloorBlock::App
{
  namespace
  {
    using Convergence::Ladder;
    using Convergence::Quantity;

    /// The quantities whose equal-error cost decides the adaptive target.
    const std::vector<std::string> target_quantities = {
      "contact_length_face", "sigma_max_averaged_face"};
    /// Target: adaptive needs at most this fraction of the uniform DoFs.
    constexpr double target_dofs_ratio = 0.25;
    constexpr unsigned int max_levels  = 10;

    void
    check_options(const CommandOptions &options)
    {
      if (options.n_levels < 2 || options.n_levels > max_levels)
        throw InputError("--levels", std::to_string(options.n_levels),
                         "2 to " + std::to_string(max_levels) +
                           " (Richardson extrapolation needs 3)");
      for (const auto &[name, value] :
           {std::pair<std::string, double>{"--bulk-fraction",
                                           options.bulk_fraction},
            {"--jump-fraction", options.jump_fraction},
            {"--target-error", options.target_error}})
        if (!(value > 0. && value <= 1.))
          throw InputError(name, fmt::format("{}", value), "0 < value <= 1");
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

    std::vector<Convergence::EqualErrorComparison>
    equal_error_comparisons(const std::vector<Ladder>   &ladders,
                            const std::vector<Quantity> &quantities,
                            const double                 target_error)
    {
      std::vector<Convergence::EqualErrorComparison> comparisons;
      if (ladders.empty() || ladders[0].mode != "uniform")
        return comparisons;
      for (std::size_t l = 1; l < ladders.size(); ++l)
        for (std::size_t q = 0; q < quantities.size(); ++q)
          comparisons.push_back(Convergence::compare_at_equal_error(
            ladders[0], ladders[l], quantities[q], q, target_error));
      return comparisons;
    }

    /// Whether adaptive meets the DoF and time targets for the face figures.
    nlohmann::json
    target_verdict(
      const std::vector<Convergence::EqualErrorComparison> &comparisons,
      const std::string                                    &adaptive_mode)
    {
      bool        evaluated = false;
      bool        met       = true;
      std::string text;
      for (const auto &comparison : comparisons)
        {
          if (comparison.adaptive_mode != adaptive_mode ||
              std::find(target_quantities.begin(), target_quantities.end(),
                        comparison.quantity) == target_quantities.end())
            continue;
          evaluated = true;
          const auto level = [](const std::optional<unsigned int> &value) {
            return value ? std::to_string(*value) : std::string("never");
          };
          const bool ok = comparison.dofs_ratio && comparison.cost_ratio &&
                          *comparison.dofs_ratio <= target_dofs_ratio &&
                          *comparison.cost_ratio < 1.;
          met = met && ok;
          text += fmt::format(
            "{}: uniform level {}, {} level {}", comparison.quantity,
            level(comparison.uniform_level), comparison.adaptive_mode,
            level(comparison.adaptive_level));
          if (comparison.dofs_ratio && comparison.cost_ratio)
            text += fmt::format(": DoFs x{:.3f}, time x{:.3f}{}",
                                *comparison.dofs_ratio, *comparison.cost_ratio,
                                comparison.ratios_are_upper_bounds ?
                                  " (upper bounds: uniform never reaches it)" :
                                  "");
          if (comparison.reference_difference)
            text += fmt::format(", best values {:.2g} apart",
                                *comparison.reference_difference);
          text += ok ? " (met); " : " (missed); ";
        }
      if (!evaluated)
        return {{"status", "not evaluated"},
                {"text", "needs the uniform and the " + adaptive_mode +
                           " ladder (--mode both or all)"}};
      return {{"status", met ? "met" : "not met"},
              {"text", text},
              {"dofs_ratio_limit", target_dofs_ratio},
              {"cost_ratio_limit", 1.}};
    }

    std::string
    ladder_text(const Ladder &ladder, const std::vector<Quantity> &quantities)
    {
      std::string text = fmt::format("{} refinement:\n", ladder.mode);
      for (std::size_t q = 0; q < quantities.size(); ++q)
        {
          const auto &errors = ladder.errors[q];
          // The order used by the extrapolation; all orders are in the JSON.
          std::string order = "-";
          if (errors.method == Convergence::ErrorMethod::richardson)
            for (const auto &observed : errors.observed_orders)
              if (observed)
                order = fmt::format("{:.2f}", *observed);
          text += fmt::format(
            "  {:<26} {:<18} order {:>6}  ref {:>13}  ({})\n",
            quantities[q].name, Convergence::method_name(errors.method),
            order,
            errors.reference ? fmt::format("{:.6e}", *errors.reference) :
                               std::string("-"),
            errors.reason);
        }
      return text;
    }
  } // namespace

  int
  converge_command(const CommandOptions &options)
  {
    dealii::Timer timer;
    check_options(options);
    const auto scene = read_scene(options);
    // The ladder refines the elastic FEM's mesh; rigid blocks have none, and
    // every level would repeat the same rigid answer.
    if (Scene::uses_rigid_blocks(scene))
      throw InputError("Model/Blocks", "rigid (or auto choosing rigid)",
                       "converge needs the elastic FEM: Model/Blocks = elastic");
    const Output::ResultFolder folder(convergence_folder(options, scene));
    folder.mark_unfinished();
    folder.write_inputs(scene);

    const auto quantities = Convergence::quantities_of_interest(
      scene.geometry.n_blocks);
    const std::string          &chosen = options.refinement_mode;
    std::vector<Pipeline::RefinementMode> modes;
    if (chosen == "uniform" || chosen == "both" || chosen == "all")
      modes.push_back(Pipeline::RefinementMode::uniform);
    if (chosen == "adaptive" || chosen == "both" || chosen == "all")
      modes.push_back(Pipeline::RefinementMode::adaptive);
    if (chosen == "remesh" || chosen == "all")
      modes.push_back(Pipeline::RefinementMode::remesh);
    Convergence::RefinementSettings refinement;
    refinement.bulk_fraction          = options.bulk_fraction;
    refinement.traction_jump_fraction = options.jump_fraction;

    std::vector<Ladder> ladders;
    bool                all_converged = true;
    for (const Pipeline::RefinementMode mode : modes)
      {
        ladders.push_back({Pipeline::mode_name(mode), {}, {}});
        const auto levels = Pipeline::run_ladder(
          scene, mode, options.n_levels, refinement, options.coarsen_fraction,
          folder,
          [&](const std::vector<Convergence::LevelRecord> &so_far) {
            ladders.back().levels = so_far;
            Convergence::estimate_ladder_errors(ladders.back(), quantities);
            write_tables(folder, ladders, quantities);
          });
        for (const auto &record : levels)
          all_converged = all_converged && record.converged();
        std::cout << ladder_text(ladders.back(), quantities);
      }

    const auto comparisons =
      equal_error_comparisons(ladders, quantities, options.target_error);
    const nlohmann::json verdict = target_verdict(comparisons, "adaptive");
    nlohmann::json       report =
      Output::convergence_json(ladders, quantities, comparisons);
    report["adaptive_target"] = verdict;
    if (chosen == "all")
      report["remesh_target"] = target_verdict(comparisons, "remesh");
    folder.write_json("convergence.json", report);
    Output::render_png(
      Output::error_vs_time_plot(ladders, quantities,
                                 scene.scene_name +
                                   ": error estimate against wall time"),
      folder.path_of("error_vs_wall_time.png"), 1300, 700);
    std::cout << "adaptive target (<= " << target_dofs_ratio
              << " of the DoFs and less time at "
              << options.target_error * 100 << " % error): "
              << verdict["status"].get<std::string>() << ". "
              << verdict["text"].get<std::string>() << std::endl;

    // Written last: its presence marks a finished study.
    folder.write_summary({{"scene", scene.scene_name},
                          {"status", all_converged ? "converged" :
                                                     "not every level converged"},
                          {"adaptive_target", verdict},
                          {"wall_time_s", timer.wall_time()}});
    std::cout << "wrote " << folder.path_of("convergence.csv") << ", "
              << folder.path_of("convergence.json") << ", "
              << folder.path_of("error_vs_wall_time.png") << " in "
              << fmt::format("{:.1f}", timer.wall_time()) << " s" << std::endl;
    return all_converged ? exit_code::success : exit_code::failure;
  }
} // namespace FloorBlock::App
