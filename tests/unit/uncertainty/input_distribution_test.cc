#include <common/input_error.h>

#include <gtest/gtest.h>
#include <openturns/CorrelationMatrix.hxx>
#include <uncertainty/input_distribution.h>

#include <cmath>

using namespace FloorBlock;
using namespace FloorBlock::Uncertainty;

namespace
{
  std::vector<Parameters::UncertainInput>
  inputs(const std::string &text)
  {
    return Parameters::parse_uncertain_inputs(text);
  }
} // namespace

TEST(InputDistribution, MarginalsHaveTheStatedMomentsAndRanges)
{
  const auto distribution =
    input_distribution(inputs("A/normal: normal(30, 3);"
                              "A/lognormal: lognormal(40e6, 10e6);"
                              "A/uniform: uniform(500, 800);"
                              "A/triangular: triangular(0, 1e4, 5e4);"
                              "A/beta: beta(2, 3, 50, 90);"
                              "A/truncated: normal(30, 3, 27, 45)"),
                       {});
  ASSERT_EQ(distribution.getDimension(), 6u);
  EXPECT_TRUE(distribution.hasIndependentCopula());
  const OT::Point mean = distribution.getMean();
  const OT::Point sd   = distribution.getStandardDeviation();
  // Closed forms: the lognormal's are its arguments; uniform (a + b)/2,
  // (b - a)/sqrt(12); triangular (a + m + b)/3; beta a + (b - a) alpha /
  // (alpha + beta); a normal cut at one sd below its mean has mean
  // mu + sd phi(-1) / (1 - Phi(-1)).
  EXPECT_NEAR(mean[0], 30., 1e-12);
  EXPECT_NEAR(sd[0], 3., 1e-12);
  EXPECT_NEAR(mean[1], 40e6, 1e-6 * 40e6);
  EXPECT_NEAR(sd[1], 10e6, 1e-6 * 10e6);
  EXPECT_NEAR(mean[2], 650., 1e-9);
  EXPECT_NEAR(sd[2], 300. / std::sqrt(12.), 1e-9);
  EXPECT_NEAR(mean[3], 6e4 / 3., 1e-6);
  EXPECT_NEAR(mean[4], 50. + 40. * 2. / 5., 1e-9);
  const double phi = std::exp(-0.5) / std::sqrt(2. * M_PI);
  const double cut = 0.5 * std::erfc(1. / std::sqrt(2.)); // Phi(-1)
  const double upper =
    0.5 * std::erfc(-5. / std::sqrt(2.)); // Phi(5): the cut at 45
  const double phi_5 = std::exp(-12.5) / std::sqrt(2. * M_PI);
  EXPECT_NEAR(mean[5], 30. + 3. * (phi - phi_5) / (upper - cut), 1e-9);
  EXPECT_EQ(distribution.getMarginal(5).getRange().getLowerBound()[0], 27.);
  EXPECT_EQ(distribution.getMarginal(5).getRange().getUpperBound()[0], 45.);
  EXPECT_EQ(distribution.getDescription()[1], "A/lognormal");
}

TEST(InputDistribution, CorrelatesThroughAGaussianCopula)
{
  const auto in = inputs("A/x: uniform(0, 1); A/y: uniform(0, 1); "
                         "A/z: normal(0, 1)");
  const auto correlations =
    Parameters::parse_input_correlations("A/y, A/x: 0.6", in);
  const auto distribution = input_distribution(in, correlations);
  EXPECT_FALSE(distribution.hasIndependentCopula());
  // The copula's own correlation matrix holds the stated values.
  const OT::CorrelationMatrix shape = distribution.getCopula().getShapeMatrix();
  EXPECT_DOUBLE_EQ(shape(0, 1), 0.6);
  EXPECT_DOUBLE_EQ(shape(1, 0), 0.6);
  EXPECT_DOUBLE_EQ(shape(0, 2), 0.);
  // Spearman's rho of a Gaussian copula: (6 / pi) asin(rho / 2).
  EXPECT_NEAR(distribution.getSpearmanCorrelation()(0, 1),
              6. / M_PI * std::asin(0.3),
              1e-6);
}

TEST(InputDistribution, RefusesCorrelationsThatCannotHoldTogether)
{
  const auto in =
    inputs("A/x: uniform(0, 1); A/y: uniform(0, 1); A/z: uniform(0, 1)");
  const auto correlations = Parameters::parse_input_correlations(
    "A/x, A/y: 0.9; A/y, A/z: 0.9; A/x, A/z: -0.9", in);
  try
    {
      input_distribution(in, correlations);
      FAIL() << "a matrix with eigenvalue 1 - 1.8 < 0 was taken";
    }
  catch (const InputError &error)
    {
      const std::string message = error.what();
      EXPECT_NE(message.find("Uncertainty/Correlations"), std::string::npos);
      EXPECT_NE(message.find("positive definite"), std::string::npos);
      EXPECT_NE(message.find("A/x, A/z: -0.9"), std::string::npos);
    }
}
