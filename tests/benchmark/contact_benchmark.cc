// Benchmark (not a test): the default scene of chapter 6.5 through the
// geometry module, compliant or rigid joints; prints Q per joint and timing.
// Usage: contact_benchmark [rigid|compliant] [output directory] [lifted]
// "lifted": flat bedding lifted into y = x^2/400 (the UDEC loading path)
// instead of blocks standing on the parabola and a 10 mm vertical uplift.
#include <contact/contact_solver.h>
#include <geometry/assembly_description.h>
#include <geometry/assembly_mesher.h>
#include <geometry/bedding_manifold.h>
#include <geometry/triangulation_reader.h>
#include <scene/floor_contact_problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <postprocess/increment_post_processor.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

int
main(int argc, char **argv)
{
  using namespace FloorBlock;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool rigid  = argc > 1 && std::string(argv[1]) == "rigid";
  const bool lifted = argc > 3 && std::string(argv[3]) == "lifted";

  dealii::Timer clock;
  Geometry::AssemblyDescription
    description; // defaults: 6 blocks 1 x 2 m on y = x^2/400
  if (lifted)
    description.floor_uplift = Geometry::FloorUplift::lifted_flat_bedding;
  const std::string msh_path = "/tmp/floorblock_benchmark.msh";
  Geometry::write_gmsh_mesh(description, msh_path);
  dealii::Triangulation<2> mesh;
  Geometry::read_triangulation(msh_path, mesh);
  Geometry::attach_bedding_manifold(description, mesh);
  const double mesh_time = clock.wall_time();

  Scene::FloorProblemSettings scene_settings;
  scene_settings.law =
    rigid ? Contact::JointLawKind::rigid : Contact::JointLawKind::compliant;
  const double degree            = M_PI / 180.;
  scene_settings.vertical_joints = {9e9, 6.7e9, 35. * degree, 0., 0.};
  scene_settings.bedding_joints  = {9e9, 6.7e9, 25. * degree, 0., 0.};
  // 650 t of support load spread over blocks 1-3 (4th-6th from the face),
  // 1 m out of plane.
  const double support_force = 650e3 * 9.81; // N
  for (unsigned int block = 1; block <= 3; ++block)
    scene_settings.support_pressures[block] = support_force / 3.;
  scene_settings.uplift.mode      = lifted ?
                                      Contact::UpliftMotion::parabola :
                                      Contact::UpliftMotion::vertical_translation;
  scene_settings.uplift.magnitude = lifted ? description.curvature : 0.01; // m
  scene_settings.steps            = {1, 2, 5};

  Contact::ContactSolverSettings settings;
  settings.verbose = true;
  if (const char *factor = std::getenv("COMPLEMENTARITY_FACTOR"))
    settings.complementarity_factor = std::atof(factor);
  if (const char *package = std::getenv("DIRECT_PACKAGE"))
    settings.linear.direct_package = package;
  if (const char *iterations = std::getenv("NEWTON_MAX_ITERATIONS"))
    settings.newton.max_iterations = std::atoi(iterations);
  if (argc > 2 && std::string(argv[2]) != "-")
    settings.output_directory = argv[2];
  clock.restart();
  Contact::ContactSolver<2> solver(
    mesh, Scene::make_floor_contact_problem(scene_settings), settings);
  const Contact::SolveResult result =
    Postprocess::solve_with_reports(solver, settings);
  const double solve_time = clock.wall_time();

  std::printf(
    "cells %u, dofs %u, contact pairs %u, mesh %.2f s, solve %.2f s\n",
    mesh.n_active_cells(),
    result.n_dofs,
    result.n_contact_pairs,
    mesh_time,
    solve_time);
  for (const auto &[section, seconds] : result.wall_times)
    std::printf("  %-28s %8.3f s\n", section.c_str(), seconds);
  const auto &last = result.increments.back();
  std::printf("%-12s %14s %14s %10s %14s %14s\n",
              "joint",
              "normal (N/m)",
              "shear (N/m)",
              "closed (m)",
              "peak (Pa)",
              "avg peak (Pa)");
  for (const auto &joint : last.joints)
    std::printf("%-12s %14.6e %14.6e %10.4f %14.6e %14.6e\n",
                joint.name.c_str(),
                joint.normal_force,
                joint.shear_force,
                joint.closed_length,
                joint.peak_normal_stress,
                joint.averaged_peak_normal_stress);
  std::printf(
    "force balance: applied (%.6e, %.6e), reaction (%.6e, %.6e), imbalance %.2e\n",
    last.balance.applied_load[0],
    last.balance.applied_load[1],
    last.balance.support_reaction[0],
    last.balance.support_reaction[1],
    last.balance.relative_imbalance);
  return 0;
}
