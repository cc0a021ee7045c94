#pragma once

#include <geometry/assembly_description.h>
#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>
#include <pipeline/fem_pipeline.h>

#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <refinement/matched_refinement.h>
#include <refinement/size_targets.h>

#include <vector>

namespace FloorBlock::Studies
{
  /**
   * @brief @p settings with its smallest size raised to the smallest size
   * request the mesher accepts for @p scene
   * (Geometry::min_relative_corner_size of the smaller block side).
   */
  Refinement::RefinementSettings
  bounded_refinement(const Refinement::RefinementSettings &settings,
                     const Parameters::ScenarioParameters &scene);

  /**
   * @brief A sequence of nested meshes of one scene, each refined where
   * the solution on the one before asked for it, with one solve per mesh.
   *
   * Level 0 is the scene's Gmsh mesh (Pipeline::mesh_scene(): contact-zone
   * sizing and Scene::global_refinements()). Each further level refines and
   * coarsens the previous level's deal.II mesh with hanging nodes where the
   * previous solution's indicators ask (the ends of the closed zones and large
   * traction jumps along the joints, Refinement::joint_size_targets; the
   * Kelly indicator in the bodies, Refinement::bulk_size_targets; the
   * floor safety's corner paths, Scene::critical_distance_sizes), both
   * sides of every joint alike (Refinement::refine_matched).
   *
   * `converge --mode adaptive` runs it as a ladder; `run` refines with it
   * until its figures reach Mesh/Target relative error (accuracy_loop.h).
   */
  class AdaptiveLevels
  {
  public:
    AdaptiveLevels(const Parameters::ScenarioParameters &scene,
                   const Refinement::RefinementSettings &refinement,
                   double                                coarsen_fraction);

    /**
     * @brief Meshes (level 0) or refines the mesh for the next level,
     * solves it into @p folder (mesh.msh, fem.json, ...; VTU if
     * @p write_vtu) and keeps what the solution asks of the level after.
     * Exceptions of the mesher or refinement propagate; a solve that did
     * not converge is returned (Pipeline::FemOutcome::converged false) and
     * still leaves indicators from its last converged state.
     */
    Pipeline::FemOutcome
    solve_next(const Output::ResultFolder  &folder,
               bool                         write_vtu,
               const Pipeline::SolveExtras &extras = {});

    /**
     * @brief Refines the last level's mesh toward @p toward (points and
     * the cell sizes asked there; cells farther away may grow by
     * @p growth_rate per unit of distance, the 2:1 rule of hanging nodes
     * grading the rest), both sides of every joint alike, no coarsening,
     * and solves it as the next level: a zoom on given points, e.g. a
     * contact corner, below the Gmsh mesher's smallest size. Pre-condition:
     * solve_next() was called.
     */
    Pipeline::FemOutcome
    solve_refined_toward(const std::vector<Geometry::LocalSize> &toward,
                         double                                  growth_rate,
                         const Output::ResultFolder             &folder,
                         bool                                    write_vtu,
                         const Pipeline::SolveExtras            &extras = {});

    /**
     * @brief Solves a copy of the last level's mesh with every cell halved
     * @p times times (new boundary vertices on the scene's curves) into
     * @p folder, without VTU: once, the nested h/2 refinement that run's
     * error estimate compares the level with (accuracy_loop.h). Leaves the
     * levels as they are. Pre-condition: solve_next() was called.
     */
    Pipeline::FemOutcome
    solve_halved(const Output::ResultFolder &folder,
                 unsigned int                times = 1) const;

    /** Whether the last level left size requests to refine from. */
    bool
    can_refine() const;

    /** Number of size requests the current level was refined with. */
    std::size_t
    n_requests_used() const;

    /** What the refinement of the last level did (empty for level 0). */
    const Refinement::MatchedRefinementSummary &
    last_refinement() const;

    /** Wall time of the last level's error indicators (s). */
    double
    last_indicator_time() const;

  private:
    /** Refines with @p with (refine_matched()) and solves the level. */
    Pipeline::FemOutcome
    refine_and_solve(const std::vector<Geometry::LocalSize> &with,
                     double                                  growth_rate,
                     double                                  coarsening,
                     unsigned int                            max_passes,
                     const Output::ResultFolder             &folder,
                     bool                                    write_vtu,
                     const Pipeline::SolveExtras            &extras);

    /** Solves the current mesh as the next level and keeps its requests. */
    Pipeline::FemOutcome
    solve_level(const Geometry::MeshStatistics &mesh,
                const Output::ResultFolder     &folder,
                bool                            write_vtu,
                const Pipeline::SolveExtras    &extras);

    const Parameters::ScenarioParameters      scene;
    const Refinement::RefinementSettings      refinement;
    const double                              coarsen_fraction;
    const Geometry::AssemblyDescription       description;
    const std::vector<Refinement::JointSides> joints;
    dealii::Triangulation<2>                  triangulation;
    unsigned int                              level = 0;
    std::vector<Geometry::LocalSize>          requests;
    std::size_t                               requests_used = 0;
    dealii::Vector<float>                     kelly;
    Refinement::MatchedRefinementSummary      refinement_done;
    double                                    indicator_time = 0.;
  };
} // namespace FloorBlock::Studies
