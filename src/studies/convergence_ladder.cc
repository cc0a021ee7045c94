#include <compare/joint_name.h>
#include <contact/contact_solver.h>
#include <geometry/assembly_description.h>
#include <geometry/refinement_manifolds.h>
#include <pipeline/fem_pipeline.h>
#include <scene/assembly_inputs.h>
#include <scene/contact_inputs.h>
#include <scene/floor_contact_problem.h>
#include <scene/mesh_sizing.h>

#include <deal.II/base/timer.h>

#include <fmt/format.h>
#include <refinement/matched_refinement.h>
#include <studies/adaptive_levels.h>
#include <studies/convergence_ladder.h>

#include <cmath>
#include <iostream>

namespace FloorBlock::Studies
{
  namespace
  {
    using Refinement::LevelRecord;

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
              record.face_contact_length = joint.closed_length;
              record.face_sigma_max      = joint.peak_normal_stress;
              record.face_sigma_max_averaged =
                joint.averaged_peak_normal_stress;
            }
        }
    }

    void
    record_outcome(const Pipeline::FemOutcome &outcome,
                   const unsigned int          n_blocks,
                   LevelRecord                &record)
    {
      record.status       = outcome.report.status;
      record.status_text  = outcome.report.status_text;
      record.n_cells      = outcome.mesh.n_cells;
      record.n_increments = outcome.result.increments.size();
      if (record.n_dofs == 0) // no solver was inspected
        {
          record.n_dofs          = outcome.result.n_dofs;
          record.n_contact_pairs = outcome.result.n_contact_pairs;
        }
      record.newton_iterations = outcome.report.n_newton_iterations;
      record.cutbacks          = outcome.report.n_cutbacks;
      record.force_balance_error =
        outcome.report.force_balance.worst_relative_error;
      record.stage_wall_times["mesh"] = outcome.mesh.wall_time;
      for (const auto &[section, seconds] : outcome.result.wall_times)
        record.stage_wall_times[section] = seconds;
      if (outcome.converged && !outcome.result.increments.empty())
        record_answers(outcome.result.increments.back(), n_blocks, record);
    }

    /** What a solved level asks of the next adaptive or remesh level. */
    struct Indicators
    {
      /** Joint and bulk size requests of the level's solution. */
      std::vector<Geometry::LocalSize> requests;
      /** Kelly indicator per active cell of the level's mesh. */
      dealii::Vector<float> kelly;
    };

    /** Solves one level's scene into a folder, given the solve extras. */
    using LevelSolve =
      std::function<Pipeline::FemOutcome(const Pipeline::SolveExtras &,
                                         const Output::ResultFolder &)>;

    /**
     * One level: @p solve (mesh and solve), and for adaptive and remesh
     * ladders the indicators for the next level (@p next).
     */
    LevelRecord
    solve_level(const Parameters::ScenarioParameters &scene,
                const RefinementMode                  mode,
                const unsigned int                    level,
                const std::size_t                     n_local_sizes,
                const Refinement::RefinementSettings &refinement,
                const Output::ResultFolder           &folder,
                const LevelSolve                     &solve,
                Indicators                           *next)
    {
      dealii::Timer timer;
      LevelRecord   record;
      record.mode               = ladder_name(mode, scene.solver.fe_degree);
      record.level              = level;
      record.corner_size        = scene.mesh.corner_size;
      record.far_size           = scene.mesh.far_size;
      record.growth_rate        = scene.mesh.growth_rate;
      record.global_refinements = Scene::global_refinements(scene);
      record.n_local_sizes      = n_local_sizes;

      Pipeline::SolveExtras extras;
      double                indicator_time = 0.;
      extras.inspect = [&](const Contact::ContactSolver<2> &solver) {
        // Also for a solve that stopped early, whose result has no DoFs.
        record.n_dofs          = solver.space().dof_handler().n_dofs();
        record.n_contact_pairs = solver.contact_nodes().size();
        if (!next)
          return;
        dealii::Timer indicator_timer;
        next->kelly =
          Refinement::kelly_indicator(solver.space(), solver.solution());
        next->requests = Refinement::bulk_size_targets(
          solver.space().dof_handler().get_triangulation(),
          next->kelly,
          refinement);
        indicator_time = indicator_timer.wall_time();
      };
      try
        {
          const Pipeline::FemOutcome outcome =
            solve(extras,
                  Output::ResultFolder(folder.path_of(record.mode + "/level_" +
                                                      std::to_string(level))));
          record_outcome(outcome, scene.geometry.n_blocks, record);
          if (next && !outcome.result.increments.empty())
            {
              dealii::Timer indicator_timer;
              const auto    joint_targets = Refinement::joint_size_targets(
                outcome.result.increments.back().joints, refinement);
              next->requests.insert(next->requests.end(),
                                    joint_targets.begin(),
                                    joint_targets.end());
              indicator_time += indicator_timer.wall_time();
            }
          if (next)
            record.stage_wall_times["indicator"] = indicator_time;
        }
      catch (const std::exception &error)
        {
          // InputError included: a size request or a mesh the geometry
          // refuses ends this level, not the study.
          record.status      = "failed";
          record.status_text = error.what();
          if (next)
            next->requests.clear();
        }
      record.wall_time = timer.wall_time();
      return record;
    }

    std::string
    progress_line(const LevelRecord &record)
    {
      return fmt::format("converge: {} level {}: {} cells, {} DoFs, {} "
                         "Newton iterations, {:.1f} s, {}{}",
                         record.mode,
                         record.level,
                         record.n_cells,
                         record.n_dofs,
                         record.newton_iterations,
                         record.wall_time,
                         record.status,
                         record.converged() ? "" :
                                              " (" + record.status_text + ")");
    }
  } // namespace

  std::string
  ladder_name(const RefinementMode mode, const unsigned int fe_degree)
  {
    return fe_degree == 1 ? mode_name(mode) :
                            mode_name(mode) + "_q" + std::to_string(fe_degree);
  }

  std::string
  mode_name(const RefinementMode mode)
  {
    switch (mode)
      {
        case RefinementMode::uniform:
          return "uniform";
        case RefinementMode::remesh:
          return "remesh";
        case RefinementMode::adaptive:
        default:
          return "adaptive";
      }
  }

  Parameters::ScenarioParameters
  uniform_level_scene(Parameters::ScenarioParameters scene,
                      const unsigned int             level)
  {
    // Nested: the level-0 mesh with every cell halved @p level more times.
    // A Gmsh re-mesh with the size function halved (what this was until
    // 2026-11-25) changes the mesh topology at every level, and with it
    // the contact-zone end by up to 5 % (rigid law at 10 deg: 82.6, 82.7,
    // 82.6 mm, then 80.6 on finer nested meshes); nested meshes are the
    // family Richardson extrapolation assumes.
    scene.mesh.global_refinements = Scene::global_refinements(scene) + level;
    return scene;
  }

  namespace
  {
    /** Level bookkeeping shared by the ladders: cost, progress, callback. */
    class LadderLog
    {
    public:
      LadderLog(const RefinementMode            mode,
                const LevelCallback            &after_level,
                const Refinement::LadderBudget &budget)
        : cumulative(mode != RefinementMode::uniform)
        , after_level(after_level)
        , budget(budget)
      {}

      /**
       * Whether the forecast of the next level fits the budget; prints the
       * forecast (time left) or why the ladder stops.
       */
      bool
      can_afford_next_level()
      {
        const auto forecast = Refinement::forecast_next_level(levels);
        const auto reason =
          Refinement::budget_stop_reason(budget, timer.wall_time(), forecast);
        if (reason)
          {
            stopped_because = "stopped before level " +
                              std::to_string(levels.back().level + 1) + ": " +
                              *reason;
            std::cout << "converge: " << levels.back().mode << " ladder "
                      << stopped_because << std::endl;
            return false;
          }
        const std::string left =
          std::isfinite(budget.seconds) ?
            fmt::format("{:.0f} s of the budget left",
                        budget.seconds - timer.wall_time()) :
            std::string("no time budget");
        std::cout
          << fmt::format("converge: {} level {} next: about {:.0f} DoFs and "
                         "{:.0f} s ({})",
                         levels.back().mode,
                         levels.back().level + 1,
                         forecast.n_dofs,
                         forecast.wall_time,
                         left)
          << std::endl;
        return true;
      }

      void
      add(LevelRecord record)
      {
        cumulative_time += record.wall_time;
        record.cost_wall_time = cumulative ? cumulative_time : record.wall_time;
        levels.push_back(record);
        std::cout << progress_line(record) << std::endl;
        after_level(levels);
      }

      /**
       * Whether a further level can start from the last one (it left size
       * requests, @p has_requests); says why not.
       */
      bool
      can_refine_from(const bool has_requests) const
      {
        if (has_requests)
          return true;
        std::cout << "converge: " << levels.back().mode
                  << " ladder stopped: level " << levels.back().level
                  << " left no solution to refine from" << std::endl;
        return false;
      }

      /** The ladder's levels and why it stopped early, if it did. */
      LadderRun
      result() const
      {
        return {levels, stopped_because};
      }

      std::vector<LevelRecord> levels;

    private:
      const bool                     cumulative;
      const LevelCallback           &after_level;
      const Refinement::LadderBudget budget;
      dealii::Timer                  timer;
      double                         cumulative_time = 0.;
      std::string                    stopped_because;
    };

    LadderRun
    run_uniform_ladder(const Parameters::ScenarioParameters &scene,
                       const unsigned int                    n_levels,
                       const Refinement::RefinementSettings &refinement,
                       const Output::ResultFolder           &folder,
                       const LevelCallback                  &after_level,
                       const Refinement::LadderBudget       &budget)
    {
      LadderLog log(RefinementMode::uniform, after_level, budget);
      for (unsigned int level = 0; level < n_levels; ++level)
        {
          if (level > 0 && !log.can_afford_next_level())
            break;
          const auto level_scene = uniform_level_scene(scene, level);
          log.add(solve_level(
            level_scene,
            RefinementMode::uniform,
            level,
            0,
            refinement,
            folder,
            [&](const Pipeline::SolveExtras &extras,
                const Output::ResultFolder  &where) {
              return Pipeline::solve_scene(level_scene, where, false, extras);
            },
            nullptr));
        }
      return log.result();
    }

    /** Each level a new Gmsh mesh with all requests so far. */
    LadderRun
    run_remesh_ladder(const Parameters::ScenarioParameters &scene,
                      const unsigned int                    n_levels,
                      const Refinement::RefinementSettings &refinement,
                      const Output::ResultFolder           &folder,
                      const LevelCallback                  &after_level,
                      const Refinement::LadderBudget       &budget)
    {
      LadderLog log(RefinementMode::remesh, after_level, budget);
      std::vector<Geometry::LocalSize> local_sizes;
      for (unsigned int level = 0; level < n_levels; ++level)
        {
          if (level > 0 && !log.can_afford_next_level())
            break;
          Indicators next;
          log.add(solve_level(
            scene,
            RefinementMode::remesh,
            level,
            local_sizes.size(),
            refinement,
            folder,
            [&](Pipeline::SolveExtras       extras,
                const Output::ResultFolder &where) {
              extras.local_sizes = local_sizes;
              return Pipeline::solve_scene(scene, where, false, extras);
            },
            &next));
          if (level + 1 < n_levels &&
              !log.can_refine_from(!next.requests.empty()))
            break;
          Refinement::merge_size_requests(local_sizes,
                                          next.requests,
                                          scene.mesh.growth_rate);
        }
      return log.result();
    }

    /**
     * Level 0 from Gmsh, then deal.II refinement with hanging nodes
     * (AdaptiveLevels).
     */
    LadderRun
    run_adaptive_ladder(const Parameters::ScenarioParameters &scene,
                        const unsigned int                    n_levels,
                        const Refinement::RefinementSettings &refinement,
                        const double                          coarsen_fraction,
                        const Output::ResultFolder           &folder,
                        const LevelCallback                  &after_level,
                        const Refinement::LadderBudget       &budget)
    {
      LadderLog      log(RefinementMode::adaptive, after_level, budget);
      AdaptiveLevels levels(scene, refinement, coarsen_fraction);
      for (unsigned int level = 0; level < n_levels; ++level)
        {
          if (level > 0 && !log.can_afford_next_level())
            break;
          LevelRecord record = solve_level(
            scene,
            RefinementMode::adaptive,
            level,
            0,
            refinement,
            folder,
            [&](const Pipeline::SolveExtras &extras,
                const Output::ResultFolder  &where) {
              return levels.solve_next(where, false, extras);
            },
            nullptr);
          record.n_local_sizes       = levels.n_requests_used();
          record.n_refinement_sweeps = levels.last_refinement().n_passes;
          record.n_cells_coarsened = levels.last_refinement().n_cells_coarsened;
          record.stage_wall_times["indicator"] = levels.last_indicator_time();
          log.add(record);
          if (level + 1 < n_levels && !log.can_refine_from(levels.can_refine()))
            break;
        }
      return log.result();
    }
  } // namespace

  LadderRun
  run_ladder(const Parameters::ScenarioParameters &scene,
             const RefinementMode                  mode,
             const unsigned int                    n_levels,
             const Refinement::RefinementSettings &refinement_settings,
             const double                          coarsen_fraction,
             const Output::ResultFolder           &folder,
             const LevelCallback                  &after_level,
             const Refinement::LadderBudget       &budget)
  {
    const auto refinement = bounded_refinement(refinement_settings, scene);
    switch (mode)
      {
        case RefinementMode::uniform:
          return run_uniform_ladder(
            scene, n_levels, refinement, folder, after_level, budget);
        case RefinementMode::remesh:
          return run_remesh_ladder(
            scene, n_levels, refinement, folder, after_level, budget);
        case RefinementMode::adaptive:
        default:
          return run_adaptive_ladder(scene,
                                     n_levels,
                                     refinement,
                                     coarsen_fraction,
                                     folder,
                                     after_level,
                                     budget);
      }
  }
} // namespace FloorBlock::Studies
