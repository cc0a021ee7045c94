#include <geometry/refinement_manifolds.h>
#include <pipeline/corner_path_refinement.h>
#include <scene/assembly_inputs.h>
#include <scene/contact_inputs.h>
#include <scene/floor_contact_problem.h>
#include <scene/mesh_sizing.h>

#include <deal.II/lac/vector.h>

namespace FloorBlock::Pipeline
{
  std::vector<Refinement::JointSides>
  matched_joint_sides(const Parameters::ScenarioParameters &scene)
  {
    std::vector<Refinement::JointSides> sides;
    for (const auto &joint :
         Scene::make_floor_contact_problem(Scene::floor_problem_settings(scene))
           .joints)
      if (!joint.against_rigid_plane)
        sides.push_back({joint.side_a, joint.side_b});
    return sides;
  }

  unsigned int
  refine_corner_paths(const Parameters::ScenarioParameters &scene,
                      dealii::Triangulation<2>             &triangulation)
  {
    const std::vector<Geometry::LocalSize> paths =
      Scene::critical_distance_sizes(scene);
    if (paths.empty())
      return 0;
    // Each sweep halves a cell once; the Gmsh cells along the paths are
    // at most a few times the request, and the 2:1 rule needs one more.
    constexpr unsigned int max_passes = 8;
    Geometry::attach_boundary_manifolds(Scene::assembly_description(scene),
                                        triangulation);
    const Refinement::MatchedRefinementSummary done =
      Refinement::refine_matched(triangulation,
                                 matched_joint_sides(scene),
                                 paths,
                                 Refinement::touching_cells_only,
                                 dealii::Vector<float>(),
                                 0.,
                                 max_passes);
    Geometry::detach_boundary_manifolds(triangulation);
    return done.n_cells_after - done.n_cells_before;
  }
} // namespace FloorBlock::Pipeline
