// Sobol' indices of the Ishigami function, known in closed form (Ishigami
// and Homma 1990; a = 7, b = 0.1, inputs uniform on [-pi, pi]):
// S1 = 0.3139, 0.4424, 0; ST = 0.5576, 0.4424, 0.2437.

#include <gtest/gtest.h>
#include <openturns/ComposedDistribution.hxx>
#include <openturns/SymbolicFunction.hxx>
#include <openturns/Uniform.hxx>
#include <uncertainty/sensitivity.h>

#include <cmath>

using namespace FloorBlock;

namespace
{
  /** The Ishigami function's indices from its variance decomposition. */
  struct Exact
  {
    double first[3];
    double total[3];
  };

  Exact
  ishigami_indices(const double a, const double b)
  {
    const double pi4 = std::pow(M_PI, 4);
    const double v1  = 0.5 * std::pow(1. + b * pi4 / 5., 2);
    const double v2  = a * a / 8.;
    const double v13 = b * b * std::pow(M_PI, 8) * (1. / 18. - 1. / 50.);
    const double v   = v1 + v2 + v13;
    return {{v1 / v, v2 / v, 0.}, {(v1 + v13) / v, v2 / v, v13 / v}};
  }
} // namespace

// Each exact index within 0.03 of the estimate and inside its 95 %
// bootstrap interval widened by 0.01 (the interval is a statistical
// statement: a fixed seed keeps the draw the same).
TEST(Sensitivity, IshigamiIndices)
{
  const OT::SymbolicFunction ishigami(
    OT::Description({"x1", "x2", "x3"}),
    OT::Description({"sin(x1) + 7 * sin(x2)^2 + 0.1 * x3^4 * sin(x1)"}));
  const OT::ComposedDistribution inputs(
    OT::ComposedDistribution::DistributionCollection(3,
                                                     OT::Uniform(-M_PI, M_PI)));
  const auto indices = Uncertainty::sobol_indices(ishigami, inputs, 20000, 0);
  const auto exact   = ishigami_indices(7., 0.1);
  EXPECT_EQ(indices.evaluations, 5u * 20000u);
  for (unsigned int i = 0; i < 3; ++i)
    {
      EXPECT_NEAR(indices.first_order[i], exact.first[i], 0.03) << i;
      EXPECT_NEAR(indices.total_order[i], exact.total[i], 0.03) << i;
      EXPECT_LE(indices.first_order_interval.getLowerBound()[i] - 0.01,
                exact.first[i]);
      EXPECT_GE(indices.first_order_interval.getUpperBound()[i] + 0.01,
                exact.first[i]);
      EXPECT_LE(indices.total_order_interval.getLowerBound()[i] - 0.01,
                exact.total[i]);
      EXPECT_GE(indices.total_order_interval.getUpperBound()[i] + 0.01,
                exact.total[i]);
    }
}
