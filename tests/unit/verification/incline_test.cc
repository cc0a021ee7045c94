// Block on an incline with Coulomb friction: it stays iff tan(alpha) < mu,
// and a stuck block's joint carries exactly W sin(alpha). The set-up is the
// library's run_incline_verification(), shared with `floorblock verify
// incline`.
#include <verification/incline_verification.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace
{
  using namespace FloorBlock;
  using namespace FloorBlock::Contact;
  using namespace FloorBlock::Verification;

  /** Incline with tan(alpha) = ratio x tan(phi) for the default phi. */
  InclineResult
  run_incline(const double ratio)
  {
    InclineSettings settings;
    settings.incline = std::atan(ratio * std::tan(settings.friction_angle));
    return run_incline_verification(settings);
  }

  TEST(Incline, StuckBelowFrictionAngle)
  {
    const InclineResult result = run_incline(0.9);
    ASSERT_FALSE(result.slipped) << "block below the friction angle slipped";
    const double incline =
      std::atan(0.9 * std::tan(InclineSettings().friction_angle));
    const JointReport &joint  = result.stuck->joints.at(0);
    const double       weight = result.weight;
    // W = rho g L H of the library's 1 x 0.5 m block, pinned so that a
    // changed default cannot make the checks below vacuous.
    EXPECT_DOUBLE_EQ(weight, 2500. * 9.81 * 1. * 0.5);
    // Equilibrium of the block alone; Newton tolerance 1e-12, so 1e-8.
    // Side A is the base, tangent (-n_y, n_x) = (-1, 0): the base holds the
    // block back against +x, so the shear traction on the joint is
    // +W sin(alpha) along -x.
    EXPECT_NEAR(std::abs(joint.shear_force),
                weight * std::sin(incline),
                1e-8 * weight);
    EXPECT_NEAR(joint.normal_force, weight * std::cos(incline), 1e-8 * weight);
    // Elastic bodies slip locally at the joint ends (Cattaneo-Mindlin
    // partial slip) even below the limit; the block as a whole sticks.
    EXPECT_GT(joint.counts.n_stick, 0u);
    std::cout << "stick/slip/open " << joint.counts.n_stick << "/"
              << joint.counts.n_slip << "/" << joint.counts.n_open << std::endl;
    EXPECT_LT(result.stuck->balance.relative_imbalance, 1e-8);
  }

  TEST(Incline, NoEquilibriumAboveFrictionAngle)
  {
    // Quasi-statics has no equilibrium for a sliding block: the solver must
    // fail with every closed pair at the slip limit in its last iterate.
    const InclineResult result = run_incline(1.1);
    ASSERT_TRUE(result.slipped)
      << "a block above the friction angle found an equilibrium";
    EXPECT_GT(result.last_iterate_counts.n_closed(), 0u);
    EXPECT_EQ(result.last_iterate_counts.n_stick, 0u);
    EXPECT_GT(result.n_failed_attempts, 0u);
    EXPECT_FALSE(result.had_converged_state);
  }
} // namespace
