// The Newton driver's stopping rules, on a scalar problem r(x) = a x - b
// whose residual cannot fall below a fixed noise level, as the residual of
// a real system cannot fall below its round-off.
#include <contact/newton_driver.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace
{
  using namespace FloorBlock::Contact;

  constexpr double slope = 4., load = 8.; // r(x) = slope x - load (N)

  struct NoisyScalarProblem
  {
    double noise = 0.; ///< residual level reached at best (N)
    double floor = 0.; ///< reported round-off floor (N)
    double x = 0., base = 0., update = 0.;
    /**
     * Solve each update only as well as the forcing term asks: the update
     * falls short by that fraction, so the linear residual is exactly
     * forcing |r| (the worst an iterative solver may return).
     */
    bool                inexact = false;
    std::vector<double> forcings; ///< as passed to solve_update
    /**
     * A pair on a kink of its law: its state, and so the set's signature,
     * changes with every Newton step while the residual does not notice.
     */
    bool          flipping  = false;
    std::uint64_t signature = 0;

    NewtonCallbacks
    callbacks()
    {
      NewtonCallbacks result;
      result.assemble = [this]() {
        NewtonIterate iterate;
        iterate.residual_norm = std::max(std::abs(slope * x - load), noise);
        iterate.set_signature = signature; // one set unless flipping
        return iterate;
      };
      result.round_off_floor = [this]() { return floor; };
      result.solve_update    = [this](const double forcing, std::string &) {
        forcings.push_back(forcing);
        if (flipping)
          signature = 1 - signature;
        update = -(slope * x - load) / slope * (inexact ? 1. - forcing : 1.);
        base   = x;
        return true;
      };
      result.set_step = [this](const double step) { x = base + step * update; };
      return result;
    }
  };

  NewtonSettings
  settings()
  {
    NewtonSettings newton;
    newton.relative_tolerance = 1e-10;
    newton.max_iterations     = 10;
    return newton;
  }

  TEST(NewtonDriver, LinearProblemConvergesInOneStep)
  {
    NoisyScalarProblem problem;
    const NewtonReport report =
      solve_newton(settings(), load, problem.callbacks());
    EXPECT_TRUE(report.converged);
    EXPECT_EQ(report.n_iterations, 1u);
    EXPECT_FALSE(report.stopped_at_round_off_floor);
  }

  TEST(NewtonDriver, ResidualStuckAboveToleranceFailsWithoutAFloor)
  {
    NoisyScalarProblem problem;
    problem.noise = 1e-9 * load; // 10 x the tolerance
    const NewtonReport report =
      solve_newton(settings(), load, problem.callbacks());
    EXPECT_FALSE(report.converged);
    EXPECT_EQ(report.failure_reason,
              "no convergence within the iteration limit");
  }

  TEST(NewtonDriver, ResidualAtTheRoundOffFloorConverges)
  {
    NoisyScalarProblem problem;
    problem.noise = 1e-9 * load;
    problem.floor = 2e-9 * load;
    const NewtonReport report =
      solve_newton(settings(), load, problem.callbacks());
    EXPECT_TRUE(report.converged);
    EXPECT_TRUE(report.stopped_at_round_off_floor);
    EXPECT_EQ(report.n_iterations, 1u);
  }

  TEST(NewtonDriver, FloorNeverRelaxesTheToleranceBeyondTheCap)
  {
    NoisyScalarProblem problem;
    // The floor covers the residual, but the residual is 1e4 x the
    // tolerance, beyond max_round_off_relief = 1e3: not converged.
    problem.noise = 1e-6 * load;
    problem.floor = 1e-5 * load;
    const NewtonReport report =
      solve_newton(settings(), load, problem.callbacks());
    EXPECT_FALSE(report.converged);
  }

  // The Eisenstat-Walker sequence, with the first solve as loose as the
  // maximum. r0 = 8 N, stop at 1e-10 * 8 N. Solve 1: eta = maximum 1e-2,
  // r1 = 0.08. Solve 2: eta = 0.9 (r1 / r0)^2 = 9e-5, r2 = 7.2e-6.
  // Solve 3: the squared ratio would ask for 7.3e-9, but half the stop
  // residual, 4e-10 / 7.2e-6 = 5.6e-5, is enough: r3 = 4e-10, converged.
  TEST(NewtonDriver, InexactSolvesFollowTheForcingTermToTheStop)
  {
    NoisyScalarProblem problem;
    problem.inexact            = true;
    NewtonSettings loose_first = settings();
    loose_first.forcing.first  = loose_first.forcing.maximum;
    const NewtonReport report =
      solve_newton(loose_first, load, problem.callbacks());
    EXPECT_TRUE(report.converged);
    EXPECT_EQ(report.n_iterations, 3u);
    ASSERT_EQ(problem.forcings.size(), 3u);
    EXPECT_DOUBLE_EQ(problem.forcings[0], ForcingSettings().maximum);
    EXPECT_NEAR(problem.forcings[1], 9e-5, 1e-12);
    EXPECT_NEAR(problem.forcings[2], 0.5 * 1e-10 * load / 7.2e-6, 1e-10);
    EXPECT_LE(report.relative_residual, 1e-10);
  }

  // With the default tight first solve (1e-8): r1 = 8e-8 N; solve 2 needs
  // only half the stop residual, 4e-10 / 8e-8 = 5e-3, and stops.
  TEST(NewtonDriver, FirstSolveOfALoadStateIsTight)
  {
    NoisyScalarProblem problem;
    problem.inexact = true;
    const NewtonReport report =
      solve_newton(settings(), load, problem.callbacks());
    EXPECT_TRUE(report.converged);
    EXPECT_EQ(report.n_iterations, 2u);
    ASSERT_EQ(problem.forcings.size(), 2u);
    EXPECT_DOUBLE_EQ(problem.forcings[0], ForcingSettings().first);
    // r1 = |4 x - 8| after x = 2 (1 - 1e-8): cancellation leaves it
    // accurate to about 1e-8 relative.
    EXPECT_NEAR(problem.forcings[1], 0.5 * 1e-10 * load / 8e-8, 1e-8 * 5e-3);
    EXPECT_LE(report.relative_residual, 1e-10);
  }
} // namespace

namespace
{
  TEST(NewtonDriver, SetThatFlipsAtTheRoundOffFloorConverges)
  {
    NoisyScalarProblem problem;
    problem.flipping = true;
    problem.noise    = 1e-12 * load; // within the tolerance
    problem.floor    = 1e-12 * load; // and all that round-off allows
    const NewtonReport report =
      solve_newton(settings(), load, problem.callbacks());
    EXPECT_TRUE(report.converged);
    EXPECT_EQ(report.n_iterations, 1u);
  }

  TEST(NewtonDriver, SetThatFlipsAboveTheRoundOffFloorDoesNotConverge)
  {
    // Within the tolerance but above round-off: the set's change is real
    // and must settle first; flipping between two sets is cycling.
    NoisyScalarProblem problem;
    problem.flipping = true;
    problem.noise    = 1e-12 * load;
    problem.floor    = 1e-14 * load;
    const NewtonReport report =
      solve_newton(settings(), load, problem.callbacks());
    EXPECT_FALSE(report.converged);
    EXPECT_EQ(report.failure_reason, "active-set cycling");
  }
} // namespace
