#include <output/gnuplot.h>

#include <deal.II/base/timer.h>

#include <fmt/format.h>
#include <studies/convergence_study.h>

#include <algorithm>
#include <optional>

namespace FloorBlock::Studies
{
  using Refinement::Ladder;
  using Refinement::Quantity;

  namespace
  {
    /// The quantities whose equal-error cost decides the adaptive target.
    const std::vector<std::string> target_quantities =
      {"contact_length_face", "sigma_max_averaged_face"};

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
    void
    run_ladders(const Parameters::ScenarioParameters &scene,
                const StudySettings                  &settings,
                const Output::ResultFolder           &folder,
                const LadderDone                     &done,
                ConvergenceStudy                     &study)
    {
      const dealii::Timer             timer;
      const std::vector<unsigned int> degrees =
        settings.fe_degrees.empty() ?
          std::vector<unsigned int>{scene.solver.fe_degree} :
          settings.fe_degrees;
      for (const unsigned int degree : degrees)
        {
          Parameters::ScenarioParameters degree_scene = scene;
          degree_scene.solver.fe_degree               = degree;
          for (const RefinementMode mode :
               refinement_modes(settings.refinement_mode))
            {
              study.ladders.push_back({ladder_name(mode, degree), {}, {}, {}});
              Ladder                  &ladder = study.ladders.back();
              Refinement::LadderBudget budget;
              budget.seconds  = settings.budget_seconds - timer.wall_time();
              budget.max_dofs = settings.max_dofs;
              const auto run  = run_ladder(
                degree_scene,
                mode,
                settings.n_levels,
                settings.refinement,
                settings.coarsen_fraction,
                folder,
                [&](const std::vector<Refinement::LevelRecord> &so_far) {
                  ladder.levels = so_far;
                  Refinement::estimate_ladder_errors(ladder, study.quantities);
                  write_tables(folder, study.ladders, study.quantities);
                },
                budget);
              ladder.stopped_because = run.stopped_because;
              for (const auto &record : run.levels)
                study.all_converged = study.all_converged && record.converged();
              done(ladder, study.quantities);
            }
        }
    }
  } // namespace

  std::vector<RefinementMode>
  refinement_modes(const std::string &choice)
  {
    std::vector<RefinementMode> modes;
    if (choice == "uniform" || choice == "both" || choice == "all")
      modes.push_back(RefinementMode::uniform);
    if (choice == "adaptive" || choice == "both" || choice == "all")
      modes.push_back(RefinementMode::adaptive);
    if (choice == "remesh" || choice == "all")
      modes.push_back(RefinementMode::remesh);
    return modes;
  }

  std::vector<Refinement::EqualErrorComparison>
  equal_error_comparisons(const std::vector<Ladder>   &ladders,
                          const std::vector<Quantity> &quantities,
                          const double                 target_error)
  {
    std::vector<Refinement::EqualErrorComparison> comparisons;
    if (ladders.empty() || ladders[0].mode != "uniform")
      return comparisons;
    for (std::size_t l = 1; l < ladders.size(); ++l)
      for (std::size_t q = 0; q < quantities.size(); ++q)
        comparisons.push_back(Refinement::compare_at_equal_error(
          ladders[0], ladders[l], quantities[q], q, target_error));
    return comparisons;
  }

  Output::TargetVerdict
  target_verdict(
    const std::vector<Refinement::EqualErrorComparison> &comparisons,
    const std::string                                   &adaptive_mode)
  {
    bool        evaluated = false;
    bool        met       = true;
    std::string text;
    for (const auto &comparison : comparisons)
      {
        if (comparison.adaptive_mode != adaptive_mode ||
            std::find(target_quantities.begin(),
                      target_quantities.end(),
                      comparison.quantity) == target_quantities.end())
          continue;
        evaluated        = true;
        const auto level = [](const std::optional<unsigned int> &value) {
          return value ? std::to_string(*value) : std::string("never");
        };
        const bool ok = comparison.dofs_ratio && comparison.cost_ratio &&
                        *comparison.dofs_ratio <= target_dofs_ratio &&
                        *comparison.cost_ratio < target_cost_ratio;
        met = met && ok;
        text += fmt::format("{}: uniform level {}, {} level {}",
                            comparison.quantity,
                            level(comparison.uniform_level),
                            comparison.adaptive_mode,
                            level(comparison.adaptive_level));
        if (comparison.dofs_ratio && comparison.cost_ratio)
          text += fmt::format(": DoFs x{:.3f}, time x{:.3f}{}",
                              *comparison.dofs_ratio,
                              *comparison.cost_ratio,
                              comparison.ratios_are_upper_bounds ?
                                " (upper bounds: uniform never reaches it)" :
                                "");
        if (comparison.reference_difference)
          text += fmt::format(", best values {:.2g} apart",
                              *comparison.reference_difference);
        text += ok ? " (met); " : " (missed); ";
      }
    if (!evaluated)
      return {false,
              false,
              "needs the uniform and the " + adaptive_mode +
                " ladder (--mode both or all)",
              target_dofs_ratio,
              target_cost_ratio};
    return {true, met, text, target_dofs_ratio, target_cost_ratio};
  }
  std::string
  degree_comparison_text(
    const std::vector<Refinement::EqualErrorComparison> &comparisons)
  {
    std::string text;
    for (const auto &comparison : comparisons)
      {
        if (comparison.adaptive_mode != "uniform_q2")
          continue;
        const auto level = [](const std::optional<unsigned int> &value) {
          return value ? "level " + std::to_string(*value) :
                         std::string("never");
        };
        text += fmt::format("\n  {}: degree 1 {}, degree 2 {}",
                            comparison.quantity,
                            level(comparison.uniform_level),
                            level(comparison.adaptive_level));
        if (comparison.dofs_ratio && comparison.cost_ratio)
          text += fmt::format(
            " (degree 2: DoFs x{:.2f}, time x{:.2f}{}; faster: degree {})",
            *comparison.dofs_ratio,
            *comparison.cost_ratio,
            comparison.ratios_are_upper_bounds ? ", upper bounds" : "",
            *comparison.cost_ratio < 1. ? 2 : 1);
        else
          text += " (neither reaches it: no comparison)";
      }
    return text;
  }

  ConvergenceStudy
  run_convergence_study(const Parameters::ScenarioParameters &scene,
                        const StudySettings                  &settings,
                        const Output::ResultFolder           &folder,
                        const LadderDone                     &ladder_done)
  {
    ConvergenceStudy study;
    study.quantities =
      Refinement::quantities_of_interest(scene.geometry.n_blocks);
    run_ladders(scene, settings, folder, ladder_done, study);
    study.comparisons     = equal_error_comparisons(study.ladders,
                                                study.quantities,
                                                settings.target_error);
    study.adaptive_target = target_verdict(study.comparisons, "adaptive");
    if (settings.refinement_mode == "all")
      study.remesh_target = target_verdict(study.comparisons, "remesh");
    folder.write_json("convergence.json",
                      Output::convergence_study_json(study.ladders,
                                                     study.quantities,
                                                     study.comparisons,
                                                     study.adaptive_target,
                                                     study.remesh_target));
    Output::render_png(
      Output::error_vs_time_plot(study.ladders,
                                 study.quantities,
                                 scene.scene_name +
                                   ": error estimate against wall time"),
      folder.path_of("error_vs_wall_time.png"),
      1300,
      700);
    return study;
  }
} // namespace FloorBlock::Studies
