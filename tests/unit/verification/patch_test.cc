// Contact patch test: two bodies pressed together over a flat joint with
// matching meshes must transmit a uniform pressure. The set-up is the
// library's run_patch_verification(), shared with `floorblock verify patch`.
#include <verification/patch_verification.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace FloorBlock;
  using namespace FloorBlock::Contact;
  using namespace FloorBlock::Verification;

  PatchResult
  run_patch_test(const JointLawKind             law,
                 const unsigned int             degree,
                 const Solver::LinearSolverKind linear_solver =
                   Solver::LinearSolverKind::direct)
  {
    PatchSettings settings;
    settings.law             = law;
    settings.fe_degree       = degree;
    settings.linear_solver   = linear_solver;
    const PatchResult result = run_patch_verification(settings);
    EXPECT_EQ(result.n_increments, 1u);
    return result;
  }

  void
  expect_uniform_pressure(const PatchResult &result)
  {
    const double       pressure = result.applied_pressure;
    const JointReport &report   = result.increment.joints.at(0);
    // The closed form comes from the library's case: pin it, so that a
    // changed default (a zero load) cannot make the checks below vacuous.
    EXPECT_EQ(pressure, 2e6);
    EXPECT_EQ(result.joint_length, 1.);
    EXPECT_EQ(report.counts.n_open, 0u);
    // Q1/Q2 represent the uniform stress exactly; what remains is the
    // direct solver's round-off (condition number ~1e6 x 1e-16) and the
    // Newton tolerance 1e-12: 1e-8 relative is a safe bound.
    for (const auto &sample : report.profile)
      EXPECT_NEAR(sample.normal_traction, pressure, 1e-8 * pressure)
        << "at x = " << sample.position[0];
    EXPECT_NEAR(report.normal_force,
                pressure * result.joint_length,
                1e-8 * pressure);
    EXPECT_NEAR(report.shear_force, 0., 1e-8 * pressure);
    EXPECT_LT(result.increment.balance.relative_imbalance, 1e-8);
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
    expect_uniform_pressure(run_patch_test(
      JointLawKind::compliant, 1, Solver::LinearSolverKind::iterative));
  }

  TEST(PatchTest, RigidLaw)
  {
    const PatchResult result = run_patch_test(JointLawKind::rigid, 1);
    expect_uniform_pressure(result);
    // Exact contact of two flat faces is linear once every pair is closed:
    // the first iterate already has the right set.
    EXPECT_LE(result.increment.n_newton_iterations, 2u);
    for (const auto &sample : result.increment.joints.at(0).profile)
      EXPECT_LT(std::abs(sample.gap), 1e-8 * 1e-3)
        << "rigid law leaves overlap";
  }
} // namespace
