// The error estimator of `floorblock converge` on synthetic ladders with a
// known limit and order: q_l = q* + C 2^(-p l) is regular, so Richardson
// must return q* and p exactly (to round-off); irregular ladders must fall
// back to the difference to the finest level.
#include <gtest/gtest.h>
#include <refinement/richardson.h>

#include <cmath>

namespace
{
  using namespace FloorBlock::Refinement;
  using Values = std::vector<std::optional<double>>;

  constexpr double limit       = 3.0e6; // q*, e.g. N/m
  constexpr double coefficient = -4.0e4;
  // Round-off of a few subtractions of numbers of size |q*|.
  constexpr double tolerance = 1e-9 * limit;

  Values
  power_law_ladder(const double order, const unsigned int n_levels)
  {
    Values values;
    for (unsigned int level = 0; level < n_levels; ++level)
      values.push_back(limit + coefficient * std::exp2(-order * level));
    return values;
  }

  void
  expect_exact_richardson(const double order)
  {
    const Values         values   = power_law_ladder(order, 5);
    const SequenceErrors estimate = estimate_errors(values);
    ASSERT_EQ(estimate.method, ErrorMethod::richardson) << estimate.reason;
    ASSERT_TRUE(estimate.reference);
    EXPECT_NEAR(*estimate.reference, limit, tolerance);
    for (unsigned int level = 2; level < 5; ++level)
      {
        ASSERT_TRUE(estimate.observed_orders[level]);
        EXPECT_NEAR(*estimate.observed_orders[level], order, 1e-9);
      }
    EXPECT_FALSE(estimate.observed_orders[0]);
    EXPECT_FALSE(estimate.observed_orders[1]);
    for (unsigned int level = 0; level < 5; ++level)
      {
        const double exact_error =
          std::abs(coefficient) * std::exp2(-order * level);
        ASSERT_TRUE(estimate.errors[level]);
        EXPECT_NEAR(*estimate.errors[level], exact_error, tolerance);
        ASSERT_TRUE(estimate.relative_errors[level]);
        EXPECT_NEAR(*estimate.relative_errors[level],
                    exact_error / limit,
                    tolerance / limit);
      }
  }

  TEST(Richardson, FirstOrderLadderIsExtrapolatedExactly)
  {
    expect_exact_richardson(1.0);
  }

  TEST(Richardson, SecondOrderLadderIsExtrapolatedExactly)
  {
    expect_exact_richardson(2.0);
  }

  TEST(Richardson, ThreeLevelsAreEnough)
  {
    const SequenceErrors estimate = estimate_errors(power_law_ladder(2., 3));
    ASSERT_EQ(estimate.method, ErrorMethod::richardson) << estimate.reason;
    EXPECT_NEAR(*estimate.reference, limit, tolerance);
  }

  TEST(Richardson, OscillationFallsBackToFinestDifference)
  {
    // Differences +, -, +, -: no geometric decay, no order.
    const Values         values   = {10., 12., 11., 11.5, 11.25};
    const SequenceErrors estimate = estimate_errors(values);
    EXPECT_EQ(estimate.method, ErrorMethod::finest_difference);
    ASSERT_TRUE(estimate.reference);
    EXPECT_DOUBLE_EQ(*estimate.reference, 11.25);
    for (unsigned int level = 0; level < 4; ++level)
      {
        ASSERT_TRUE(estimate.errors[level]);
        EXPECT_DOUBLE_EQ(*estimate.errors[level],
                         std::abs(*values[level] - 11.25));
      }
    // The finest level is the reference: it has no estimate of its own.
    EXPECT_FALSE(estimate.errors[4]);
    EXPECT_FALSE(estimate.relative_errors[4]);
  }

  TEST(Richardson, InconsistentOrdersFallBack)
  {
    // Differences 1, 1/2, 1/32: orders 1 then 4, beyond the band of 1.
    const Values         values   = {0., 1., 1.5, 1.5 + 1. / 32.};
    const SequenceErrors estimate = estimate_errors(values);
    EXPECT_EQ(estimate.method, ErrorMethod::finest_difference);
    ASSERT_TRUE(estimate.observed_orders[2] && estimate.observed_orders[3]);
    EXPECT_NEAR(*estimate.observed_orders[2], 1., 1e-12);
    EXPECT_NEAR(*estimate.observed_orders[3], 4., 1e-12);
  }

  TEST(Richardson, GrowingDifferencesFallBack)
  {
    // Same sign, growing: negative observed order.
    const Values         values   = {0., 1., 3.};
    const SequenceErrors estimate = estimate_errors(values);
    EXPECT_EQ(estimate.method, ErrorMethod::finest_difference);
    ASSERT_TRUE(estimate.observed_orders[2]);
    EXPECT_NEAR(*estimate.observed_orders[2], -1., 1e-12);
  }

  TEST(Richardson, NonConvergedLevelIsNeverUsed)
  {
    // A regular ladder whose level 3 failed: the finest three usable levels
    // (1, 2, 4) are not consecutive halvings, so no extrapolation.
    Values values = power_law_ladder(2., 5);
    values[3].reset();
    const SequenceErrors estimate = estimate_errors(values);
    EXPECT_EQ(estimate.method, ErrorMethod::finest_difference);
    EXPECT_FALSE(estimate.errors[3]);
    EXPECT_DOUBLE_EQ(*estimate.reference, *values[4]);
    // A failed coarsest level does not matter: 1..4 are regular.
    Values late = power_law_ladder(2., 5);
    late[0].reset();
    EXPECT_EQ(estimate_errors(late).method, ErrorMethod::richardson);
  }

  TEST(Richardson, OneLevelHasNoEstimate)
  {
    const SequenceErrors estimate = estimate_errors({1.0, std::nullopt});
    EXPECT_EQ(estimate.method, ErrorMethod::unavailable);
    EXPECT_FALSE(estimate.errors[0]);
  }

  TEST(Richardson, UnchangedQuantityHasZeroError)
  {
    // E.g. Q = 0 at an open joint on every level.
    const SequenceErrors estimate = estimate_errors({0., 0., 0.});
    EXPECT_EQ(estimate.method, ErrorMethod::finest_difference);
    EXPECT_DOUBLE_EQ(*estimate.errors[0], 0.);
    EXPECT_FALSE(estimate.relative_errors[0]); // relative to 0: none
  }
} // namespace

namespace
{
  TEST(Richardson, RoundOffDifferencesGiveNoOrder)
  {
    // Q_1 of a free end block is fixed by equilibrium: the levels differ
    // only by round-off, which must not be read as an order.
    const double                                 q = 1.882586952e6;
    const FloorBlock::Refinement::SequenceErrors estimate =
      FloorBlock::Refinement::estimate_errors(
        {q * (1. + 4e-13), q * (1. + 1e-13), q * (1. + 9e-14)});
    EXPECT_EQ(estimate.method,
              FloorBlock::Refinement::ErrorMethod::finest_difference);
    EXPECT_LT(*estimate.relative_errors[0], 1e-12);
  }
} // namespace
