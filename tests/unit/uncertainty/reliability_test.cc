// P(FS < 1) and the design point on a safety factor with an exact answer:
// FS = 1 + R - S with R ~ N(5, 1) and S ~ N(2, 1) independent fails where
// R - S < 0, a normal margin of mean 3 and standard deviation sqrt(2):
// beta = 3 / sqrt(2), P_f = Phi(-beta) = 0.0169474, and the design point
// is the mean moved along the gradient to the limit, (3.5, 3.5).

#include <gtest/gtest.h>
#include <openturns/ComposedDistribution.hxx>
#include <openturns/DistFunc.hxx>
#include <openturns/Normal.hxx>
#include <openturns/SymbolicFunction.hxx>
#include <uncertainty/reliability.h>

#include <cmath>
#include <stdexcept>

using namespace FloorBlock;

namespace
{
  const double exact_beta = 3. / std::sqrt(2.);

  OT::ComposedDistribution
  resistance_and_load()
  {
    OT::ComposedDistribution::DistributionCollection marginals;
    marginals.add(OT::Normal(5., 1.));
    marginals.add(OT::Normal(2., 1.));
    return OT::ComposedDistribution(marginals);
  }

  const OT::SymbolicFunction
    linear_safety_factor(OT::Description({"R", "S"}),
                         OT::Description({"1 + R - S"}));
} // namespace

// FORM is exact for a linear limit state in normal inputs.
TEST(Reliability, FormIsExactForALinearLimitState)
{
  const auto result =
    Uncertainty::form_design_point(linear_safety_factor, resistance_and_load());
  EXPECT_NEAR(result.reliability_index, exact_beta, 1e-6);
  EXPECT_NEAR(result.probability, OT::DistFunc::pNormal(-exact_beta), 1e-8);
  ASSERT_EQ(result.point.getDimension(), 2u);
  EXPECT_NEAR(result.point[0], 3.5, 1e-4);
  EXPECT_NEAR(result.point[1], 3.5, 1e-4);
}

// Monte Carlo stops at the half-width asked for, and its 95 % interval
// holds the exact P_f (a fixed seed: the same draw every run).
TEST(Reliability, MonteCarloIntervalHoldsTheExactProbability)
{
  Uncertainty::SimulationSettings settings;
  settings.half_width      = 0.002;
  settings.max_evaluations = 1000000;
  settings.seed            = 1;
  const auto result =
    Uncertainty::monte_carlo_failure_probability(linear_safety_factor,
                                                 resistance_and_load(),
                                                 settings);
  const double exact = OT::DistFunc::pNormal(-exact_beta);
  EXPECT_LE(result.half_width, settings.half_width);
  EXPECT_LE(std::abs(result.probability - exact), result.half_width)
    << result.probability << " +- " << result.half_width;
  // The binomial standard deviation sqrt(p (1 - p) / n) sets n.
  const double n_needed =
    exact * (1. - exact) * std::pow(1.96 / settings.half_width, 2);
  EXPECT_NEAR(result.evaluations / n_needed, 1., 0.1) << result.evaluations;
}

// A budget smaller than the half-width needs stops at the budget.
TEST(Reliability, MonteCarloStopsAtItsBudget)
{
  Uncertainty::SimulationSettings settings;
  settings.half_width      = 1e-4;
  settings.max_evaluations = 2000;
  const auto result =
    Uncertainty::monte_carlo_failure_probability(linear_safety_factor,
                                                 resistance_and_load(),
                                                 settings);
  EXPECT_EQ(result.evaluations, 2000u);
  EXPECT_GT(result.half_width, settings.half_width);
}

TEST(Reliability, RefusesAFunctionOfOtherInputs)
{
  const OT::SymbolicFunction one_input(OT::Description({"R"}),
                                       OT::Description({"R"}));
  EXPECT_THROW(Uncertainty::form_design_point(one_input, resistance_and_load()),
               std::invalid_argument);
}
