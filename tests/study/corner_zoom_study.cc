// Study (not a test): the face joint's floor-level corner under nested
// local refinement (issue 15). Level 0 is the scene's mesh; every further
// level halves the cells at the corner -- along both top fillets of the
// face joint, or at its sharp corner -- with hanging nodes, graded by
// growth 1.5 away from it, so the corner cells shrink geometrically while
// the far field stays. Prints one line per level: what the face joint's
// peak, averaged peak and contact length do when only the corner is
// refined, below the Gmsh mesher's 1 mm.
// Usage: corner_zoom_study <scene.prm> <levels> <output folder>
//          ["Subsection/Entry=value"]...
#include <contact/contact_solver.h>
#include <contact/joint_pairing.h>
#include <geometry/body_outline.h>
#include <geometry/ids.h>
#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>
#include <pipeline/adaptive_levels.h>
#include <scene/assembly_inputs.h>
#include <scene/mesh_refinement.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
  using namespace FloorBlock;

  /** Points along both top fillets of joint n, or its sharp top end. */
  std::vector<Geometry::Point2>
  face_corner_points(const Parameters::ScenarioParameters &scene)
  {
    const Geometry::AssemblyOutline outline =
      Geometry::build_outline(Scene::assembly_description(scene));
    const unsigned int            n = scene.geometry.n_blocks;
    std::vector<Geometry::Point2> points;
    for (const Geometry::FilletPair &pair : outline.fillet_pairs)
      if (pair.master.body == n - 1)
        for (const Geometry::SegmentRef &ref : {pair.master, pair.slave})
          {
            const Geometry::Segment &arc =
              outline.bodies[ref.body].segments[ref.segment];
            const double radius =
              std::hypot(arc.start.x - arc.control.x, arc.start.y - arc.control.y);
            const double from = std::atan2(arc.start.y - arc.control.y,
                                           arc.start.x - arc.control.x);
            double to = std::atan2(arc.end.y - arc.control.y,
                                   arc.end.x - arc.control.x);
            if (to - from > M_PI)
              to -= 2. * M_PI;
            if (from - to > M_PI)
              to += 2. * M_PI;
            constexpr unsigned int n_samples = 16;
            for (unsigned int k = 0; k <= n_samples; ++k)
              {
                const double angle = from + (to - from) * k / n_samples;
                points.push_back({arc.control.x + radius * std::cos(angle),
                                  arc.control.y + radius * std::sin(angle)});
              }
          }
    if (points.empty()) // sharp: the upper end of joint n's side
      for (const Geometry::JointPair &pair : outline.joint_pairs)
        if (pair.master.body == n - 1)
          {
            const Geometry::Segment &side =
              outline.bodies[pair.master.body].segments[pair.master.segment];
            if (std::abs(side.end.x - side.start.x) > 1e-9)
              continue;
            points.push_back(side.start.y > side.end.y ? side.start : side.end);
          }
    return points;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 4)
    {
      std::fprintf(stderr,
                   "usage: %s <scene.prm> <levels> <output folder> "
                   "[\"Subsection/Entry=value\"]...\n",
                   argv[0]);
      return 2;
    }
  std::vector<std::string> overrides(argv + 4, argv + argc);
  const auto   scene    = Parameters::read_scenario(argv[1], overrides);
  const int    n_levels = std::atoi(argv[2]);
  const std::string root = argv[3];

  const auto points = face_corner_points(scene);
  double     size   = scene.mesh.corner_size *
                std::exp2(-double(Scene::global_refinements(scene)));
  Pipeline::AdaptiveLevels levels(
    scene, Pipeline::bounded_refinement({}, scene), 0.);
  std::printf("%5s %8s %10s %13s %13s %13s %10s %10s %7s\n", "level", "DoFs",
              "corner h", "Q (N/m)", "peak (Pa)", "avg peak", "peak y",
              "contact", "time s");
  for (int level = 0; level <= n_levels; ++level)
    {
      dealii::Timer              clock;
      const Output::ResultFolder folder(root + "/level_" +
                                        std::to_string(level));
      Pipeline::FemOutcome outcome;
      if (level == 0)
        outcome = levels.solve_next(folder, false);
      else
        {
          size /= 2.;
          std::vector<Geometry::LocalSize> toward;
          for (const auto &point : points)
            toward.push_back({point, size});
          Pipeline::SolveExtras extras;
          extras.inspect = [&](const Contact::ContactSolver<2> &solver) {
            // Whether the facing fillets still pair (mirror images).
            const unsigned int      n = scene.geometry.n_blocks;
            Contact::PairingSummary summary;
            Contact::pair_joint_nodes(solver.space(),
                                      Geometry::Ids::vertical_joint_free_side(n),
                                      Geometry::Ids::vertical_joint_face_side(n),
                                      n, &summary);
            std::printf("      pairing: %u coincident, %u mirrored, %u + %u free\n",
                        summary.n_coincident, summary.n_mirrored,
                        summary.n_free_a, summary.n_free_b);
          };
          outcome = levels.solve_refined_toward(toward, 1.5, folder, false, extras);
        }
      if (!outcome.converged || outcome.result.increments.empty())
        {
          std::printf("%5d failed: %s\n", level,
                      outcome.report.status_text.c_str());
          return 1;
        }
      for (const auto &joint : outcome.result.increments.back().joints)
        if (joint.name == "vertical " + std::to_string(scene.geometry.n_blocks))
          std::printf("%5d %8u %10.3e %13.6e %13.6e %13.6e %10.6f %10.6f %7.1f\n",
                      level, outcome.result.n_dofs, size, joint.normal_force,
                      joint.peak_normal_stress,
                      joint.averaged_peak_normal_stress, joint.peak_position[1],
                      joint.closed_length, clock.wall_time());
      std::fflush(stdout);
    }
  return 0;
}
