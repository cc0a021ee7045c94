// Contact patch test: two bodies pressed together over a flat joint with
// matching meshes must transmit a uniform pressure.
#include "block_mesh.h"
#include "test_scenes.h"

#include <contact/contact_solver.h>

#include <gtest/gtest.h>

#include <deal.II/grid/tria.h>

namespace
{
  using namespace FloorBlock;
  using namespace FloorBlock::Contact;

  // Test-local ids: bodies 1 (lower) and 2 (upper).
  constexpr dealii::types::boundary_id lower_left = 11, lower_right = 12,
                                       lower_bottom = 13, lower_top = 14;
  constexpr dealii::types::boundary_id upper_left = 21, upper_right = 22,
                                       upper_bottom = 23, upper_top = 24;
  constexpr double applied_pressure = 2e6; // Pa

  IncrementResult
  run_patch_test(const JointLawKind              law,
                 const unsigned int            degree,
                 const Solver::LinearSolverKind linear_solver =
                   Solver::LinearSolverKind::direct)
  {
    dealii::Triangulation<2> mesh;
    Testing::make_block_assembly(
      {{0., 1., 0., 1., 4, 3, 1, lower_left, lower_right, lower_bottom, lower_top},
       {0., 1., 1., 2., 4, 5, 2, upper_left, upper_right, upper_bottom, upper_top}},
      mesh);
    SceneDefinition<2> scene;
    scene.model.laws.emplace(1, Testing::table_rock());
    scene.model.laws.emplace(2, Testing::table_rock());
    scene.model.pressures[upper_top] = applied_pressure;
    // Rollers: uniform uniaxial stress is then the exact solution, and
    // both bodies expand laterally alike, so the joint shear is zero.
    scene.supports = {Testing::fixed_support(lower_bottom, false, true),
                      Testing::fixed_support(lower_left, true, false),
                      Testing::fixed_support(upper_left, true, false)};
    JointDefinition<2> joint;
    joint.name                        = "patch";
    joint.side_a                      = lower_top;
    joint.side_b                      = upper_bottom;
    joint.law                         = law;
    joint.parameters.normal_stiffness = 1e12;
    joint.parameters.shear_stiffness  = 1e12;
    joint.parameters.friction_angle   = 0.5;
    scene.joints                      = {joint};
    scene.steps                       = {0, 1, 0};
    ContactSolverSettings settings = Testing::test_settings(degree);
    settings.linear.kind           = linear_solver;
    ContactSolver solver(mesh, scene, settings);
    const SolveResult result = solver.run();
    EXPECT_EQ(result.increments.size(), 1u);
    return result.increments.back();
  }

  void
  expect_uniform_pressure(const IncrementResult &increment)
  {
    const JointReport &report = increment.joints.at(0);
    EXPECT_EQ(report.counts.n_open, 0u);
    // Q1/Q2 represent the uniform stress exactly; what remains is the
    // direct solver's round-off (condition number ~1e6 x 1e-16) and the
    // Newton tolerance 1e-12: 1e-8 relative is a safe bound.
    for (const auto &sample : report.profile)
      EXPECT_NEAR(sample.normal_traction, applied_pressure, 1e-8 * applied_pressure)
        << "at x = " << sample.position[0];
    EXPECT_NEAR(report.normal_force, applied_pressure * 1.0, 1e-8 * applied_pressure);
    EXPECT_NEAR(report.shear_force, 0., 1e-8 * applied_pressure);
    EXPECT_LT(increment.balance.relative_imbalance, 1e-8);
  }

  TEST(PatchTest, CompliantLawDegreeOne)
  {
    expect_uniform_pressure(run_patch_test(JointLawKind::compliant, 1));
  }

  TEST(PatchTest, CompliantLawDegreeTwo)
  {
    expect_uniform_pressure(run_patch_test(JointLawKind::compliant, 2));
  }

  TEST(PatchTest, AlgebraicMultigridGmres)
  {
    // ML AMG + GMRES stops at 1e-10 relative residual per Newton step;
    // Newton then drives the nonlinear residual to 1e-12, so the same 1e-8
    // bound holds.
    expect_uniform_pressure(run_patch_test(JointLawKind::compliant,
                                           1,
                                           Solver::LinearSolverKind::iterative));
  }

  TEST(PatchTest, RigidLaw)
  {
    const IncrementResult increment = run_patch_test(JointLawKind::rigid, 1);
    expect_uniform_pressure(increment);
    EXPECT_GT(increment.n_multiplier_updates, 1u);
    for (const auto &sample : increment.joints.at(0).profile)
      EXPECT_LT(std::abs(sample.gap), 1e-8 * 1e-3) << "rigid law leaves overlap";
  }
} // namespace
