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

TEST(CornerFit, IntensitiesWithGivenExponentsRecoverBothTerms)
{
  const auto samples = edge_field(2e10, -1.5e11);
  const auto k       = Corner::intensities_with_exponents(samples, 1.5, 2.);
  EXPECT_NEAR(k.first / 2e10, 1., 1e-9);
  EXPECT_NEAR(k.second / -1.5e11, 1., 1e-9);
}

TEST(CornerFit, TwoTermFitFindsTheSquareRootExponent)
{
  Corner::CornerTheory theory;
  theory.exponent      = 1.5;
  theory.next_exponent = 2.;
  const auto samples   = edge_field(2e10, -1.5e11);
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
  const auto apart = Corner::converged_range(edge_field(2e10, 0., 1.1), coarse,
                                             0.01, 0., 1.);
  EXPECT_EQ(apart.n_samples, 0u);
  EXPECT_EQ(apart.to, 0.);
}
