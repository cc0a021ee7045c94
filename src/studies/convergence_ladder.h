#pragma once

#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>

#include <refinement/ladder_budget.h>
#include <refinement/level_record.h>
#include <refinement/size_targets.h>

#include <functional>
#include <string>
#include <vector>

namespace FloorBlock::Studies
{
  /** How the levels of a ladder are refined. */
  enum class RefinementMode
  {
    /**
     * Every level halves every cell of the level before (deal.II global
     * refinement, new boundary vertices on the scene's curves), so
     * h_l(x) = h_0(x) / 2^l everywhere on nested meshes
     * (uniform_level_scene()).
     */
    uniform,
    /**
     * Level 0 is uniform level 0 (the scene's Gmsh mesh); each further
     * level refines and coarsens the previous level's mesh in deal.II
     * (hanging nodes), where the previous solution's indicators ask for
     * smaller cells (Refinement::joint_size_targets, bulk_size_targets)
     * and coarsens the smoothest cells, with both sides of every joint
     * refined alike (Refinement::refine_matched).
     */
    adaptive,
    /**
     * Level 0 is uniform level 0; each further level re-meshes with Gmsh
     * with the size requests of all previous levels' indicators added: the
     * same requests as adaptive, realised by a global size field.
     */
    remesh
  };

  /** @brief "uniform", "adaptive" or "remesh". */
  std::string
  mode_name(const RefinementMode mode);

  /**
   * @brief The name of a ladder in convergence.csv/json, its level folders
   * and the plot: mode_name(), with "_q2" appended when the scene's
   * Solver/FE degree is 2 (converge --degrees runs one ladder per degree).
   */
  std::string
  ladder_name(const RefinementMode mode, const unsigned int fe_degree);

  /**
   * @brief The scene of uniform level @p level: the same Gmsh mesh with
   * @p level more global refinements (Scene::global_refinements()), so
   * every cell is halved @p level times more.
   */
  Parameters::ScenarioParameters
  uniform_level_scene(Parameters::ScenarioParameters scene,
                      const unsigned int             level);

  /** Called after every level with all levels so far (partial results). */
  using LevelCallback =
    std::function<void(const std::vector<Refinement::LevelRecord> &)>;

  /** @brief The levels of one ladder and why it stopped early, if it did. */
  struct LadderRun
  {
    std::vector<Refinement::LevelRecord> levels;
    /** Empty if every requested level ran (or the ladder had nothing to refine
     * from). */
    std::string stopped_because;
  };

  /**
   * @brief Runs @p n_levels full solves of the loading path, each into
   * <folder>/<mode>/level_<l>/ (mesh.msh, fem.json, joints.csv). A level
   * that does not converge or fails (mesh or solver error) is recorded
   * with its status and the ladder goes on; an adaptive or remesh ladder
   * stops early if a level leaves no solution to refine from.
   * @p coarsen_fraction: adaptive mode, fraction of cells flagged for
   * coarsening per level (Refinement::flag_smooth_cells_for_coarsening).
   * Before every level after the first the ladder forecasts its DoFs and
   * wall time (Refinement::forecast_next_level) and stops if they exceed
   * @p budget (the time counted from this call), saying so.
   */
  LadderRun
  run_ladder(const Parameters::ScenarioParameters &scene,
             const RefinementMode                  mode,
             const unsigned int                    n_levels,
             const Refinement::RefinementSettings &refinement,
             const double                          coarsen_fraction,
             const Output::ResultFolder           &folder,
             const LevelCallback                  &after_level,
             const Refinement::LadderBudget       &budget);
} // namespace FloorBlock::Studies
