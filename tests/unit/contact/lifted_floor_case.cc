#include "lifted_floor_case.h"

#include <scene/floor_contact_problem.h>

#include <postprocess/increment_post_processor.h>

#include <cmath>

#include "rounded_mesh.h"

namespace FloorBlock::Testing
{
  namespace
  {
    /** Curvature k of the lift u_y = x^2/k (m): the chapter's default scene. */
    constexpr double lift_curvature = 400.;
    /** Table 6.1 joint stiffnesses kn, ks (Pa/m). */
    constexpr double normal_stiffness = 9e9;
    constexpr double shear_stiffness  = 6.7e9;
    /** Friction angles of vertical and bedding joints (deg). */
    constexpr double vertical_friction_degrees = 35.;
    constexpr double bedding_friction_degrees  = 25.;
    /** 650 t of support load spread over blocks 1-3, 1 m out of plane (N). */
    constexpr double       support_force = 650e3 * 9.81;
    constexpr unsigned int n_supported   = 3;
  } // namespace

  LiftedFloorOutcome
  run_lifted_floor(const LiftedFloorCase &floor_case)
  {
    Geometry::AssemblyDescription description =
      level_assembly(floor_case.n_blocks,
                     floor_case.rounding,
                     floor_case.corner_size);
    description.bedding_shape = Geometry::BeddingShape::parabolic;
    description.curvature     = lift_curvature;
    description.floor_uplift  = Geometry::FloorUplift::lifted_flat_bedding;
    dealii::Triangulation<2> mesh;
    mesh_assembly(description, "lifted_floor", mesh);

    Scene::FloorProblemSettings settings;
    settings.n_blocks        = floor_case.n_blocks;
    settings.law             = floor_case.law;
    const double degree      = M_PI / 180.;
    settings.vertical_joints = {normal_stiffness,
                                shear_stiffness,
                                vertical_friction_degrees * degree,
                                0.,
                                0.};
    settings.bedding_joints  = {normal_stiffness,
                                shear_stiffness,
                                bedding_friction_degrees * degree,
                                0.,
                                0.};
    if (floor_case.support_load)
      for (unsigned int block = 1; block <= n_supported; ++block)
        settings.support_pressures[block] = support_force / n_supported;
    settings.uplift.mode      = Contact::UpliftMotion::parabola;
    settings.uplift.magnitude = lift_curvature;
    settings.steps            = {1, floor_case.support_load ? 2u : 0u, 5};

    Contact::ContactSolverSettings solver_settings;
    solver_settings.averaging_length       = floor_case.averaging_length;
    solver_settings.extrapolate_increments = floor_case.extrapolate_increments;
    Contact::ContactSolver<2> solver(
      mesh, Scene::make_floor_contact_problem(settings), solver_settings);
    const Contact::SolveResult result =
      Postprocess::solve_with_reports(solver, solver_settings);
    LiftedFloorOutcome outcome;
    outcome.last    = result.increments.back();
    outcome.n_cells = mesh.n_active_cells();
    outcome.n_pairs = result.n_contact_pairs;
    for (const auto &increment : result.increments)
      outcome.n_newton_iterations += increment.n_newton_iterations;
    return outcome;
  }
} // namespace FloorBlock::Testing
