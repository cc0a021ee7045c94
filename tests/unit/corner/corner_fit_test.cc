#include <corner/corner_fit.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace FloorBlock;

  /** t = k1 d^(1/2) + k2 d on a geometric grid from 1e-6 to 1e-3 m. */
  std::vector<Analytic::RadialSample>
  edge_field(const double k1, const double k2, const double scale = 1.)
  {
    std::vector<Analytic::RadialSample> samples;
    for (double d = 1e-6; d <= 1e-3; d *= 1.1)
      samples.push_back({d, scale * (k1 * std::sqrt(d) + k2 * d)});
    return samples;
  }
} // namespace

static Corner::CornerTheory
edge_theory()
{
  Corner::CornerTheory theory;
  theory.exponent       = 1.5;
  theory.next_exponent  = 2.;
  theory.third_exponent = 2.5;
  return theory;
}

TEST(CornerFit, IntensitiesWithTheTheorysExponentsRecoverEveryTerm)
{
  auto samples = edge_field(2e10, -1.5e11);
  for (auto &sample : samples)
    sample.traction += 4e11 * std::pow(sample.distance, 1.5);
  const auto k = Corner::theory_intensities(samples, edge_theory());
  EXPECT_NEAR(k.first / 2e10, 1., 1e-8);
  EXPECT_NEAR(k.second / -1.5e11, 1., 1e-8);
}

// A third term biases the two-term fit; the three-term expansion is exact.
TEST(CornerFit, ExpansionFitRemovesTheThirdTermsBias)
{
  auto samples = edge_field(2e10, -1.5e11);
  for (auto &sample : samples)
    sample.traction += 1.5e13 * std::pow(sample.distance, 1.5);
  const auto fit = Corner::fit_corner(samples, {1e-5, 3e-4, 0}, edge_theory());
  EXPECT_NEAR(fit.expansion.lambda1, 1.5, 1e-3);
  EXPECT_GT(std::abs(fit.two_terms.lambda1 - 1.5), 5e-3);
}

TEST(CornerFit, TwoTermFitFindsTheSquareRootExponent)
{
  Corner::CornerTheory theory = edge_theory();
  theory.third_exponent       = 0.; // two terms
  const auto samples          = edge_field(2e10, -1.5e11);
  const auto fit = Corner::fit_corner(samples, {1e-5, 1e-4, 0}, theory);
  EXPECT_NEAR(fit.two_terms.lambda1, 1.5, 1e-3);
  // The one-term slope is biased by the second term: that is why both exist.
  EXPECT_GT(std::abs(fit.one_term.lambda1 - 1.5), 1e-3);
  EXPECT_NEAR(fit.intensity.first / 2e10, 1., 1e-9);
  // |K2/K1| d^(1/2) = 0.1 at d = (0.1 * 2e10 / 1.5e11)^2.
  EXPECT_NEAR(fit.validity_distance, std::pow(0.1 * 2e10 / 1.5e11, 2.), 1e-9);
}

TEST(CornerFit, ConvergedRangeIsWhereTwoLevelsAgree)
{
  const auto coarse = edge_field(2e10, 0.);
  auto       fine   = edge_field(2e10, 0.);
  // The fine level differs by 5 % below 2e-5 m (the edge's discretisation).
  for (auto &sample : fine)
    if (sample.distance < 2e-5)
      sample.traction *= 1.05;
  const auto range = Corner::converged_range(fine, coarse, 0.01, 0., 5e-4);
  EXPECT_GE(range.from, 2e-5);
  EXPECT_LT(range.from, 2.2e-5);
  EXPECT_LE(range.to, 5e-4);
  EXPECT_GT(range.to, 4.5e-4);
  // Nothing agrees: no range.
  const auto apart =
    Corner::converged_range(edge_field(2e10, 0., 1.1), coarse, 0.01, 0., 1.);
  EXPECT_EQ(apart.n_samples, 0u);
  EXPECT_EQ(apart.to, 0.);
}

// The mean pressure carries a constant (the uniform lambda = 1 mode) under
// the edge's terms; the fit must find lambda1 = 3/2 beside it, not run off
// to where d^(lambda1 - 1) merges with the constant.
TEST(CornerFit, InvariantFitFindsTheEdgeExponentBesideAConstant)
{
  std::vector<Analytic::RadialSample> samples;
  for (double d = 2e-5; d <= 2.4e-4; d *= 1.02)
    samples.push_back({d, 9.8e7 + 4e9 * std::sqrt(d) - 2e11 * d});
  const auto fit =
    Corner::fit_invariant(samples, {2e-5, 2.4e-4, 0}, edge_theory());
  EXPECT_NEAR(fit.lambda1, 1.5, 1e-3);
}
