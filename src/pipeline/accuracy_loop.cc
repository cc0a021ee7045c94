#include <pipeline/accuracy_loop.h>
#include <pipeline/adaptive_levels.h>
#include <pipeline/error_estimate.h>
#include <scene/rigid_inputs.h>

#include <deal.II/base/timer.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>

namespace FloorBlock::Pipeline
{
  namespace
  {
    using Parameters::TargetFigure;

    Output::FigureError Output::JointErrors::*
    figure_error(const TargetFigure figure)
    {
      switch (figure)
        {
          case TargetFigure::normal_force:
            return &Output::JointErrors::normal_force;
          case TargetFigure::contact_length:
            return &Output::JointErrors::contact_length;
          case TargetFigure::sigma_max:
            return &Output::JointErrors::sigma_max;
          case TargetFigure::sigma_max_averaged:
          default:
            return &Output::JointErrors::sigma_max_averaged;
        }
    }

    std::string
    face_joint(const Parameters::ScenarioParameters &scene)
    {
      return "vertical " + std::to_string(scene.geometry.n_blocks);
    }

    Output::RefinementLevelRecord
    level_record(const unsigned int                    level,
                 const FemOutcome                     &outcome,
                 const double                          wall_time,
                 const Parameters::ScenarioParameters &scene)
    {
      Output::RefinementLevelRecord record;
      record.level     = level;
      record.n_cells   = outcome.mesh.n_cells;
      record.n_dofs    = outcome.result.n_dofs;
      record.wall_time = wall_time;
      record.status    = outcome.report.status;
      if (outcome.converged && !outcome.result.increments.empty())
        for (const auto &joint : outcome.result.increments.back().joints)
          if (joint.name == face_joint(scene))
            record.face_figures = {
              {"normal_force_N_per_m", joint.normal_force},
              {"contact_length_m", joint.closed_length},
              {"sigma_max_Pa", joint.peak_normal_stress},
              {"sigma_max_averaged_Pa", joint.averaged_peak_normal_stress}};
      return record;
    }

    /**
     * The next level's size and time from the last two levels' growth (the
     * first step: the level-1 growth is not known, so no forecast).
     */
    double
    forecast_wall_time(const std::vector<Output::RefinementLevelRecord> &levels)
    {
      if (levels.size() < 2)
        return 0.;
      const auto &last     = levels.back();
      const auto &previous = levels[levels.size() - 2];
      if (!(previous.wall_time > 0.))
        return last.wall_time;
      return last.wall_time *
             std::max(1., last.wall_time / previous.wall_time);
    }

    /** Copies the reported level's solve files over level 0's. */
    void
    promote_level_files(const Output::ResultFolder &level_folder,
                        const Output::ResultFolder &folder)
    {
      namespace fs = std::filesystem;
      for (const char *name : {"fem.json", "joints.csv", "joint_profiles.csv",
                               "mesh.msh", "deformed.png"})
        if (fs::exists(level_folder.path_of(name)))
          fs::copy_file(level_folder.path_of(name), folder.path_of(name),
                        fs::copy_options::overwrite_existing);
      if (fs::exists(level_folder.path_of("vtu")))
        {
          fs::remove_all(folder.path_of("vtu"));
          fs::copy(level_folder.path_of("vtu"), folder.path_of("vtu"),
                   fs::copy_options::recursive);
        }
    }

    std::string
    percent(const std::optional<double> &fraction)
    {
      if (!fraction)
        return "not estimated";
      if (!std::isfinite(*fraction))
        return "unbounded";
      return fmt::format("{:.2g} %", 100. * *fraction);
    }
  } // namespace

  std::string
  target_figure_key(const TargetFigure figure)
  {
    switch (figure)
      {
        case TargetFigure::normal_force:
          return "normal_force_N_per_m";
        case TargetFigure::contact_length:
          return "contact_length_m";
        case TargetFigure::sigma_max:
          return "sigma_max_Pa";
        case TargetFigure::sigma_max_averaged:
        default:
          return "sigma_max_averaged_Pa";
      }
  }

  std::optional<double>
  worst_target_error(const Output::FemErrorEstimate              &estimate,
                     const std::string                           &joint,
                     const std::vector<Parameters::TargetFigure> &figures)
  {
    if (!estimate.available || estimate.joints.count(joint) == 0)
      return std::nullopt;
    const Output::JointErrors &errors = estimate.joints.at(joint);
    double                     worst  = 0.;
    for (const TargetFigure figure : figures)
      {
        const Output::FigureError &error = errors.*figure_error(figure);
        const double               relative =
          error.relative_error ? *error.relative_error :
          error.absolute_error == 0. ?
                                 0. :
                                 std::numeric_limits<double>::infinity();
        worst = std::max(worst, relative);
      }
    return worst;
  }

  TargetedSolve
  solve_to_target(const Parameters::ScenarioParameters &scene,
                  const Output::ResultFolder           &folder)
  {
    if (Scene::uses_rigid_blocks(scene) ||
        !scene.solver.estimate_error_by_refined_solve)
      {
        TargetedSolve solve{solve_scene(scene, folder), std::nullopt};
        solve.estimate = estimate_error(scene, solve.outcome, folder);
        return solve;
      }

    dealii::Timer          timer;
    Output::AccuracyTarget target;
    target.relative_error = scene.mesh.target_relative_error;
    for (const TargetFigure figure : scene.mesh.target_figures)
      target.figures.push_back(target_figure_key(figure));

    AdaptiveLevels levels(
      scene, bounded_refinement(Convergence::RefinementSettings(), scene),
      Convergence::default_coarsen_fraction);
    const auto level_folder = [&](const unsigned int level) {
      return level == 0 ? folder :
                          Output::ResultFolder(folder.path_of(
                            "refined/level_" + std::to_string(level)));
    };

    // Every level's outcome is kept: the reported one is the coarser of
    // the last pair compared, which is not always the last solved.
    std::vector<FemOutcome> outcomes;
    dealii::Timer           level_timer;
    outcomes.push_back(levels.solve_next(folder, true));
    target.levels.push_back(
      level_record(0, outcomes[0], level_timer.wall_time(), scene));
    if (!outcomes[0].converged)
      return {outcomes[0], std::nullopt}; // nothing to estimate: fem.json says why

    Output::FemErrorEstimate estimate;
    estimate.status_text = "no refined level was solved";
    for (unsigned int level = 1;; ++level)
      {
        if (!levels.can_refine())
          {
            target.stop_reason = fmt::format(
              "level {} left no size request to refine from", level - 1);
            break;
          }
        const double forecast = forecast_wall_time(target.levels);
        if (level > 1 && timer.wall_time() + forecast >
                           scene.mesh.refinement_time_budget)
          {
            target.stop_reason = fmt::format(
              "level {} would end after about {:.0f} s, past Mesh/Refinement "
              "time budget = {:g} s",
              level, timer.wall_time() + forecast,
              scene.mesh.refinement_time_budget);
            break;
          }
        level_timer.restart();
        outcomes.push_back(levels.solve_next(level_folder(level), true));
        const FemOutcome &finer = outcomes.back();
        target.levels.push_back(
          level_record(level, finer, level_timer.wall_time(), scene));
        estimate = refined_solve_error(outcomes[level - 1], finer);
        const auto worst = worst_target_error(estimate, face_joint(scene),
                                              scene.mesh.target_figures);
        target.levels[level - 1].worst_target_error = worst;
        target.reported_level = level - 1;
        std::cout << fmt::format(
                       "accuracy: level {}: {} DoFs, {:.1f} s; level {}'s "
                       "target figures within {} (target {})",
                       level, finer.result.n_dofs, level_timer.wall_time(),
                       level - 1, percent(worst),
                       percent(target.relative_error))
                  << std::endl;
        if (!estimate.available)
          {
            target.stop_reason = estimate.status_text;
            break;
          }
        if (*worst <= target.relative_error)
          {
            target.met         = true;
            target.stop_reason = fmt::format(
              "target met on level {} (estimated from level {})", level - 1,
              level);
            break;
          }
        if (level >= scene.mesh.max_refinement_levels)
          {
            target.stop_reason =
              fmt::format("Mesh/Maximum refinement levels = {} reached",
                          scene.mesh.max_refinement_levels);
            break;
          }
      }
    if (target.reported_level > 0)
      promote_level_files(level_folder(target.reported_level), folder);
    target.wall_time = timer.wall_time();
    if (!target.met)
      std::cout << "accuracy: target not met: " << target.stop_reason
                << std::endl;
    estimate.target = target;
    return {std::move(outcomes[target.reported_level]), estimate};
  }
} // namespace FloorBlock::Pipeline
