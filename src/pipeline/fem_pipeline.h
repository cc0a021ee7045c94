#pragma once

#include <contact/results.h>
#include <geometry/assembly_mesher.h>
#include <output/fem_report.h>
#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>

#include <deal.II/grid/tria.h>

#include <functional>
#include <vector>

namespace FloorBlock::Contact
{
  template <int dim>
  class ContactSolver;
} // namespace FloorBlock::Contact

namespace FloorBlock::Pipeline
{
  /** What meshing and solving a scene produced. */
  struct FemOutcome
  {
    Geometry::MeshStatistics mesh;
    Contact::SolveResult     result; ///< converged increments only
    bool                     converged = false;
    Output::FemReport        report; ///< written as fem.json
  };

  /** Optional extras of solve_scene(), for refinement studies. */
  struct SolveExtras
  {
    /** Solution-driven size requests for the mesher (adaptive re-meshing). */
    std::vector<Geometry::LocalSize> local_sizes;
    /**
     * Called with the solver after the loading path ended (converged or
     * not; its solution() is then the last converged state), e.g. to
     * evaluate error indicators while the solution still exists.
     */
    std::function<void(const Contact::ContactSolver<2> &)> inspect;
  };

  /**
   * @brief Meshes the scene with Gmsh (into the result folder as mesh.msh),
   * runs the contact solver through the loading stages and writes fem.json
   * and joints.csv (and VTU files under vtu/). A solve that fails after
   * its cutbacks is reported, not thrown: fem.json then holds the last
   * converged increment with status "not converged" and what was tried.
   * A scene with Model/Blocks = rigid (or auto choosing rigid) is solved
   * by solve_rigid_scene() instead (rigid_pipeline.h): no mesh, no VTU,
   * the same fem.json and joints.csv; fem.json's "model" names the model.
   * A 3D scene (Geometry/Dimension = 3) goes to solve_swept_scene(); the
   * extras are 2D only.
   */
  FemOutcome
  solve_scene(const Parameters::ScenarioParameters &scene,
              const Output::ResultFolder           &folder,
              const bool                            write_vtu = true,
              const SolveExtras                    &extras    = {});

  /**
   * @brief The Gmsh mesh of the scene (with @p local_sizes, adaptive
   * re-meshing) read into @p triangulation, refined
   * Scene::global_refinements() times and along the floor safety's corner
   * paths (refine_corner_paths()); the mesh solved on is written into
   * @p folder as mesh.msh: solve_scene()'s first half.
   */
  Geometry::MeshStatistics
  mesh_scene(const Parameters::ScenarioParameters   &scene,
             const Output::ResultFolder             &folder,
             const std::vector<Geometry::LocalSize> &local_sizes,
             dealii::Triangulation<2>               &triangulation);

  /**
   * @brief Writes @p triangulation as Gmsh .msh to @p msh_path (atomically)
   * and puts its cell and node counts into @p statistics.
   */
  template <int dim>
  void
  write_solved_mesh(const dealii::Triangulation<dim> &triangulation,
                    const std::string                &msh_path,
                    Geometry::MeshStatistics         &statistics);

  /**
   * @brief solve_scene() on a mesh the caller made (e.g. refined by deal.II
   * in `converge --mode adaptive`): the same solve and files, except that
   * no mesh.msh is written and @p mesh describes the mesh in fem.json.
   */
  FemOutcome
  solve_meshed_scene(const Parameters::ScenarioParameters &scene,
                     const dealii::Triangulation<2>       &triangulation,
                     const Geometry::MeshStatistics       &mesh,
                     const Output::ResultFolder           &folder,
                     const bool                            write_vtu,
                     const SolveExtras                    &extras);

  /**
   * @brief Throws InputError, naming the parameter, if the 3D scene
   * cannot be solved: the rigid-block model (2D only) or global
   * refinements (Mesh/Global refinements, "auto" included), which the
   * swept mesh does not take. Commands call it before writing anything.
   */
  void
  check_swept_scene(const Parameters::ScenarioParameters &scene);

  /**
   * @brief The 3D scene's mesh (Geometry/Dimension = 3): the Gmsh mesh of
   * the scene's cross-section swept along the face over Geometry/Face
   * length in slices of Mesh/Slice size (Geometry::extrude_assembly),
   * through both ends of a support footprint if there is one, whose
   * loaded tops then carry Ids::footprint_surface
   * (Scene::swept_slices, Scene::tag_support_footprint); written into
   * @p folder as mesh.msh. Throws as check_swept_scene().
   */
  Geometry::MeshStatistics
  mesh_swept_scene(const Parameters::ScenarioParameters &scene,
                   const Output::ResultFolder           &folder,
                   dealii::Triangulation<3>             &solid);

  /**
   * @brief solve_scene() for a 3D scene, on one process: the mesh of
   * mesh_swept_scene(), the scene's 2D contact problem swept along the
   * face with Geometry/End faces (Scene::swept_contact_problem), the same
   * contact solver and files, forces per metre of face and contact areas
   * (Postprocess::make_swept_joint_reports), each joint along the face. With a
   * footprint the support's whole load acts on it
   * (Scene::load_support_footprint); fem.json reports the support force
   * the mesh carries (applied_load_N, Fem::applied_surface_load). No
   * deformed.png (a 2D picture).
   * Throws as check_swept_scene().
   */
  FemOutcome
  solve_swept_scene(const Parameters::ScenarioParameters &scene,
                    const Output::ResultFolder           &folder,
                    const bool                            write_vtu);

  /** @brief fem.json and joints.csv of a solve, into @p folder. */
  void
  write_fem_files(const FemOutcome           &outcome,
                  const Output::ResultFolder &folder);
} // namespace FloorBlock::Pipeline
