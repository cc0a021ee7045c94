#include <contact/contact_solver.h>
#include <geometry/refinement_manifolds.h>
#include <pipeline/corner_path_refinement.h>
#include <scene/assembly_inputs.h>
#include <scene/contact_inputs.h>
#include <scene/floor_contact_problem.h>
#include <scene/mesh_sizing.h>

#include <deal.II/base/timer.h>

#include <studies/adaptive_levels.h>

#include <algorithm>
#include <filesystem>

namespace FloorBlock::Studies
{
  Refinement::RefinementSettings
  bounded_refinement(const Refinement::RefinementSettings &settings,
                     const Parameters::ScenarioParameters &scene)
  {
    Refinement::RefinementSettings refinement = settings;
    refinement.smallest_size =
      std::max(refinement.smallest_size,
               Geometry::min_relative_corner_size *
                 std::min(scene.geometry.block_width,
                          scene.geometry.block_height));
    return refinement;
  }

  AdaptiveLevels::AdaptiveLevels(
    const Parameters::ScenarioParameters &scene,
    const Refinement::RefinementSettings &refinement,
    const double                          coarsen_fraction)
    : scene(scene)
    , refinement(refinement)
    , coarsen_fraction(coarsen_fraction)
    , description(Scene::assembly_description(scene))
    , joints(Pipeline::matched_joint_sides(scene))
  {}

  Pipeline::FemOutcome
  AdaptiveLevels::solve_next(const Output::ResultFolder  &folder,
                             const bool                   write_vtu,
                             const Pipeline::SolveExtras &extras)
  {
    if (level == 0)
      {
        refinement_done = {};
        requests_used   = 0;
        const Geometry::MeshStatistics mesh =
          Pipeline::mesh_scene(scene, folder, {}, triangulation);
        return solve_level(mesh, folder, write_vtu, extras);
      }
    // A zone end asks for a quarter of its segment (zone_end_refinement
    // = 4: two halvings); one more sweep lets the 2:1 grading follow.
    constexpr unsigned int                 max_passes   = 3;
    const std::vector<Geometry::LocalSize> own_requests = requests;
    return refine_and_solve(own_requests,
                            Refinement::touching_cells_only,
                            coarsen_fraction,
                            max_passes,
                            folder,
                            write_vtu,
                            extras);
  }

  Pipeline::FemOutcome
  AdaptiveLevels::solve_refined_toward(
    const std::vector<Geometry::LocalSize> &toward,
    const double                            growth_rate,
    const Output::ResultFolder             &folder,
    const bool                              write_vtu,
    const Pipeline::SolveExtras            &extras)
  {
    Assert(level > 0, dealii::ExcMessage("solve level 0 first"));
    // Each sweep halves a cell once: enough sweeps to go from the coarsest
    // cell to the smallest request.
    constexpr unsigned int max_passes = 40;
    return refine_and_solve(
      toward, growth_rate, 0., max_passes, folder, write_vtu, extras);
  }

  Pipeline::FemOutcome
  AdaptiveLevels::refine_and_solve(const std::vector<Geometry::LocalSize> &with,
                                   const double                 growth_rate,
                                   const double                 coarsening,
                                   const unsigned int           max_passes,
                                   const Output::ResultFolder  &folder,
                                   const bool                   write_vtu,
                                   const Pipeline::SolveExtras &extras)
  {
    requests_used = with.size();
    dealii::Timer            timer;
    Geometry::MeshStatistics mesh;
    Geometry::attach_boundary_manifolds(description, triangulation);
    refinement_done = Refinement::refine_matched(
      triangulation, joints, with, growth_rate, kelly, coarsening, max_passes);
    Geometry::detach_boundary_manifolds(triangulation);
    std::filesystem::create_directories(folder.path_of(""));
    Pipeline::write_solved_mesh(triangulation,
                                folder.path_of("mesh.msh"),
                                mesh);
    mesh.wall_time = timer.wall_time();
    return solve_level(mesh, folder, write_vtu, extras);
  }

  Pipeline::FemOutcome
  AdaptiveLevels::solve_level(const Geometry::MeshStatistics &mesh,
                              const Output::ResultFolder     &folder,
                              const bool                      write_vtu,
                              const Pipeline::SolveExtras    &extras)
  {
    ++level;
    requests.clear();
    indicator_time = 0.;

    Pipeline::SolveExtras own = extras;
    own.inspect               = [&](const Contact::ContactSolver<2> &solver) {
      if (extras.inspect)
        extras.inspect(solver);
      dealii::Timer timer;
      kelly    = Refinement::kelly_indicator(solver.space(), solver.solution());
      requests = Refinement::bulk_size_targets(
        solver.space().dof_handler().get_triangulation(), kelly, refinement);
      indicator_time += timer.wall_time();
    };
    Pipeline::FemOutcome outcome = Pipeline::solve_meshed_scene(
      scene, triangulation, mesh, folder, write_vtu, own);
    if (!outcome.result.increments.empty())
      {
        dealii::Timer timer;
        const auto    joint_targets = Refinement::joint_size_targets(
          outcome.result.increments.back().joints, refinement);
        requests.insert(requests.end(),
                        joint_targets.begin(),
                        joint_targets.end());
        // The floor safety factor's corner paths keep the cells the Gmsh
        // mesh gave them (Mesh/Cells per critical distance): coarsening
        // where the indicators are small would leave a path unresolved.
        const auto corner_targets = Scene::critical_distance_sizes(scene);
        requests.insert(requests.end(),
                        corner_targets.begin(),
                        corner_targets.end());
        indicator_time += timer.wall_time();
      }
    return outcome;
  }

  Pipeline::FemOutcome
  AdaptiveLevels::solve_halved(const Output::ResultFolder &folder,
                               const unsigned int          times) const
  {
    dealii::Timer            timer;
    dealii::Triangulation<2> halved;
    halved.copy_triangulation(triangulation);
    Geometry::refine_globally_on_curves(description, times, halved);
    Geometry::MeshStatistics mesh;
    std::filesystem::create_directories(folder.path_of(""));
    Pipeline::write_solved_mesh(halved, folder.path_of("mesh.msh"), mesh);
    mesh.wall_time = timer.wall_time();
    return Pipeline::solve_meshed_scene(scene, halved, mesh, folder, false, {});
  }

  bool
  AdaptiveLevels::can_refine() const
  {
    return !requests.empty();
  }

  std::size_t
  AdaptiveLevels::n_requests_used() const
  {
    return requests_used;
  }

  const Refinement::MatchedRefinementSummary &
  AdaptiveLevels::last_refinement() const
  {
    return refinement_done;
  }

  double
  AdaptiveLevels::last_indicator_time() const
  {
    return indicator_time;
  }
} // namespace FloorBlock::Studies
