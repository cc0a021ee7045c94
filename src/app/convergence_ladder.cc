#include <app/convergence_ladder.h>
#include <app/fem_pipeline.h>
#include <compare/joint_name.h>
#include <contact/contact_solver.h>
#include <geometry/assembly_description.h>

#include <deal.II/base/timer.h>

#include <fmt/format.h>

#include <cmath>
#include <iostream>

namespace FloorBlock::App
{
  namespace
  {
    using Convergence::LevelRecord;

    /** Normal forces of the vertical joints and the face-joint figures. */
    void
    record_answers(const Contact::IncrementResult &last,
                   const unsigned int              n_blocks,
                   LevelRecord                    &record)
    {
      record.joint_normal_forces.assign(n_blocks, 0.);
      for (const auto &joint : last.joints)
        {
          const auto name = Compare::parse_joint_name(joint.name);
          if (name.kind != "vertical" || name.number < 1 ||
              name.number > n_blocks)
            continue;
          record.joint_normal_forces[name.number - 1] = joint.normal_force;
          if (name.number == n_blocks)
            {
              record.face_contact_length     = joint.closed_length;
              record.face_sigma_max          = joint.peak_normal_stress;
              record.face_sigma_max_averaged = joint.averaged_peak_normal_stress;
            }
        }
    }

    void
    record_outcome(const FemOutcome &outcome,
                   const unsigned int n_blocks,
                   LevelRecord      &record)
    {
      record.status      = outcome.fem["status"].get<std::string>();
      record.status_text = outcome.fem["status_text"].get<std::string>();
      record.n_cells      = outcome.mesh.n_cells;
      record.n_increments = outcome.result.increments.size();
      if (record.n_dofs == 0) // no solver was inspected
        {
          record.n_dofs          = outcome.result.n_dofs;
          record.n_contact_pairs = outcome.result.n_contact_pairs;
        }
      record.newton_iterations =
        outcome.fem["newton_iterations"].get<unsigned int>();
      record.cutbacks = outcome.fem["cutbacks"].get<unsigned int>();
      record.force_balance_error =
        outcome.fem["force_balance_relative_error"].get<double>();
      record.stage_wall_times["mesh"] = outcome.mesh.wall_time;
      for (const auto &[section, seconds] : outcome.result.wall_times)
        record.stage_wall_times[section] = seconds;
      if (outcome.converged && !outcome.result.increments.empty())
        record_answers(outcome.result.increments.back(), n_blocks, record);
    }

    /** Smallest size request the mesher accepts for this scene (m). */
    double
    smallest_local_size(const Parameters::ScenarioParameters &scene)
    {
      return Geometry::min_relative_corner_size *
             std::min(scene.geometry.block_width, scene.geometry.block_height);
    }

    /**
     * One level: mesh (with @p local_sizes), solve, and for adaptive
     * ladders the size requests for the next level (@p next_targets).
     */
    LevelRecord
    solve_level(const Parameters::ScenarioParameters  &scene,
                const RefinementMode                   mode,
                const unsigned int                     level,
                const std::vector<Geometry::LocalSize> &local_sizes,
                const Convergence::RefinementSettings  &refinement,
                const Output::ResultFolder             &folder,
                std::vector<Geometry::LocalSize>       *next_targets)
    {
      dealii::Timer timer;
      LevelRecord   record;
      record.mode          = mode_name(mode);
      record.level         = level;
      record.corner_size   = scene.mesh.corner_size;
      record.far_size      = scene.mesh.far_size;
      record.growth_rate   = scene.mesh.growth_rate;
      record.n_local_sizes = local_sizes.size();

      SolveExtras extras;
      extras.local_sizes = local_sizes;
      double indicator_time = 0.;
      extras.inspect = [&](const Contact::ContactSolver &solver) {
        // Also for a solve that stopped early, whose result has no DoFs.
        record.n_dofs          = solver.space().dof_handler().n_dofs();
        record.n_contact_pairs = solver.contact_nodes().size();
        if (!next_targets)
          return;
        dealii::Timer indicator_timer;
        *next_targets = Convergence::bulk_size_targets(
          solver.space(), solver.solution(), refinement);
        indicator_time = indicator_timer.wall_time();
      };
      try
        {
          const FemOutcome outcome = solve_scene(
            scene,
            Output::ResultFolder(folder.path_of(
              record.mode + "/level_" + std::to_string(level))),
            false,
            extras);
          record_outcome(outcome, scene.geometry.n_blocks, record);
          if (next_targets && !outcome.result.increments.empty())
            {
              dealii::Timer indicator_timer;
              const auto joint_targets = Convergence::joint_size_targets(
                outcome.result.increments.back().joints, refinement);
              next_targets->insert(next_targets->end(), joint_targets.begin(),
                                   joint_targets.end());
              indicator_time += indicator_timer.wall_time();
            }
          if (next_targets)
            record.stage_wall_times["indicator"] = indicator_time;
        }
      catch (const std::exception &error)
        {
          // InputError included: a size request or a mesh the geometry
          // refuses ends this level, not the study.
          record.status      = "failed";
          record.status_text = error.what();
          if (next_targets)
            next_targets->clear();
        }
      record.wall_time = timer.wall_time();
      return record;
    }

    std::string
    progress_line(const LevelRecord &record)
    {
      return fmt::format("converge: {} level {}: {} cells, {} DoFs, {} "
                         "Newton iterations, {:.1f} s, {}{}",
                         record.mode, record.level, record.n_cells,
                         record.n_dofs, record.newton_iterations,
                         record.wall_time, record.status,
                         record.converged() ? "" :
                                              " (" + record.status_text + ")");
    }
  } // namespace

  std::string
  mode_name(const RefinementMode mode)
  {
    return mode == RefinementMode::uniform ? "uniform" : "adaptive";
  }

  Parameters::ScenarioParameters
  uniform_level_scene(Parameters::ScenarioParameters scene,
                      const unsigned int             level)
  {
    const double scale = std::exp2(-static_cast<double>(level));
    scene.mesh.corner_size *= scale;
    scene.mesh.far_size *= scale;
    scene.mesh.growth_rate = 1. + (scene.mesh.growth_rate - 1.) * scale;
    return scene;
  }

  std::vector<Convergence::LevelRecord>
  run_ladder(const Parameters::ScenarioParameters  &scene,
             const RefinementMode                   mode,
             const unsigned int                     n_levels,
             const Convergence::RefinementSettings &refinement_settings,
             const Output::ResultFolder            &folder,
             const LevelCallback                   &after_level)
  {
    Convergence::RefinementSettings refinement = refinement_settings;
    refinement.smallest_size =
      std::max(refinement.smallest_size, smallest_local_size(scene));
    std::vector<LevelRecord>         levels;
    std::vector<Geometry::LocalSize> local_sizes;
    double                           cumulative_time = 0.;
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        std::vector<Geometry::LocalSize> targets;
        const bool adaptive = mode == RefinementMode::adaptive;
        LevelRecord record =
          solve_level(adaptive ? scene : uniform_level_scene(scene, level),
                      mode, level, local_sizes, refinement, folder,
                      adaptive ? &targets : nullptr);
        cumulative_time += record.wall_time;
        record.cost_wall_time = adaptive ? cumulative_time : record.wall_time;
        levels.push_back(record);
        std::cout << progress_line(record) << std::endl;
        after_level(levels);
        if (adaptive && level + 1 < n_levels)
          {
            if (targets.empty())
              {
                std::cout << "converge: adaptive ladder stopped: level "
                          << level << " left no solution to refine from"
                          << std::endl;
                break;
              }
            Convergence::merge_size_requests(local_sizes, targets,
                                             scene.mesh.growth_rate);
          }
      }
    return levels;
  }
} // namespace FloorBlock::App
