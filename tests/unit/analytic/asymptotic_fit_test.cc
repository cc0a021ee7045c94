// Fits of a corner's traction to its eigen-expansion, on synthetic data.
#include <analytic/asymptotic_fit.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace FloorBlock::Analytic;

namespace
{
  /** p = K1 r^(l1-1) + K2 r^(l2-1) at 30 distances from 1e-4 to 3e-2 m. */
  std::vector<RadialSample>
  two_term_samples(const double l1,
                   const double k1,
                   const double l2,
                   const double k2)
  {
    std::vector<RadialSample> samples;
    for (int i = 0; i < 30; ++i)
      {
        const double r = 1e-4 * std::pow(300., i / 29.);
        samples.push_back(
          {r, k1 * std::pow(r, l1 - 1.) + k2 * std::pow(r, l2 - 1.)});
      }
    return samples;
  }
} // namespace

TEST(OneTermFit, RecoversAPurePowerLaw)
{
  const auto fit = one_term_fit(two_term_samples(0.6, 3e6, 0.9, 0.));
  EXPECT_NEAR(fit.lambda1, 0.6, 1e-12);
  EXPECT_NEAR(fit.k1, 3e6, 1e-6 * 3e6);
  EXPECT_LT(fit.rms_relative_residual, 1e-12);
}

// The stuck square corner's case: exponents 0.5445 and 0.9085 with a
// second term 1.4 times the first (what `verify punch` measures). The
// one-term fit is biased by several hundredths; the two-term fit with the
// second exponent given recovers the first.
TEST(TwoTermFit, RecoversTheFirstExponentWhereTheOneTermFitIsBiased)
{
  const auto samples = two_term_samples(0.5445, 5e6, 0.9085, 1.4 * 5e6);
  EXPECT_GT(one_term_fit(samples).lambda1 - 0.5445, 0.03);
  const auto fit = two_term_fit(samples, 0.9085);
  EXPECT_NEAR(fit.lambda1, 0.5445, 1e-6);
  EXPECT_NEAR(fit.k2 / fit.k1, 1.4, 1e-5);
  EXPECT_LT(fit.rms_relative_residual, 1e-8);
  // |K2/K1| r^0.364 = 0.1 at r = (0.1 / 1.4)^(1 / 0.364).
  EXPECT_NEAR(one_term_validity_distance(fit, 0.1),
              std::pow(0.1 / 1.4, 1. / (0.9085 - 0.5445)),
              1e-6);
}

// With 1 % noise (alternating, like nodal tractions at hanging nodes) the
// first exponent stays within 0.01.
TEST(TwoTermFit, ToleratesAlternatingNoise)
{
  auto samples = two_term_samples(0.5445, 5e6, 0.9085, 1.4 * 5e6);
  for (std::size_t i = 0; i < samples.size(); ++i)
    samples[i].traction *= i % 2 == 0 ? 1.01 : 0.99;
  EXPECT_NEAR(two_term_fit(samples, 0.9085).lambda1, 0.5445, 0.01);
}

TEST(TwoTermFit, TooFewSamplesGiveNoFit)
{
  const auto fit = two_term_fit({{1e-3, 1.}, {2e-3, 0.8}}, 0.9);
  EXPECT_EQ(fit.n_samples, 2u);
  EXPECT_EQ(fit.lambda1, 0.);
}
