#include <gtest/gtest.h>
#include <openturns/ComposedDistribution.hxx>
#include <openturns/LHSExperiment.hxx>
#include <openturns/LogNormalMuSigma.hxx>
#include <openturns/MonteCarloExperiment.hxx>
#include <openturns/Normal.hxx>
#include <openturns/RandomGenerator.hxx>
#include <openturns/SymbolicFunction.hxx>
#include <openturns/Uniform.hxx>
#include <uncertainty/surrogate.h>

#include <cmath>

using namespace FloorBlock::Uncertainty;

namespace
{
  OT::Distribution
  inputs()
  {
    OT::ComposedDistribution::DistributionCollection marginals;
    marginals.add(OT::Normal(30., 3.));
    marginals.add(OT::LogNormalMuSigma(9e9, 4.5e9).getDistribution());
    marginals.add(OT::Uniform(500., 800.));
    return OT::ComposedDistribution(marginals);
  }

  /** A smooth safety-factor-like function: x1 in degrees, x2 a stiffness. */
  const OT::SymbolicFunction
    model(OT::Description({"phi", "kn", "load"}),
          OT::Description({"tan(phi * 3.14159265358979 / 180) * 2 - "
                           "0.1 * log(kn / 9e9) - 0.0005 * (load - 650)"}));
} // namespace

TEST(Surrogate, ChoosesTheChaosThatReproducesAPolynomialExactly)
{
  // A quadratic in the normal score of x and linear in y: degree 2 holds it.
  OT::ComposedDistribution::DistributionCollection marginals;
  marginals.add(OT::Normal(1., 2.));
  marginals.add(OT::Normal(-1., 0.5));
  const OT::ComposedDistribution distribution(marginals);
  const OT::SymbolicFunction     polynomial(
    OT::Description({"x", "y"}), OT::Description({"x^2 - 3 * x * y + y"}));
  OT::RandomGenerator::SetSeed(3);
  const OT::Sample x         = OT::LHSExperiment(distribution, 40).generate();
  const Surrogate  surrogate = fit_surrogate(x, polynomial(x), distribution, 4);
  EXPECT_LT(surrogate.cross_validation_rms, 1e-8);
  EXPECT_EQ(surrogate.chaos_degree, 2u);
  const OT::Sample test = distribution.getSample(100);
  const auto       check =
    held_out_errors(surrogate.model, test, polynomial(test), 1e-7);
  EXPECT_LT(check.largest, 1e-7);
  EXPECT_EQ(check.share_within_stated, 1.);
}

TEST(Surrogate, CrossValidationForecastsTheHeldOutError)
{
  OT::RandomGenerator::SetSeed(7);
  const OT::Distribution distribution = inputs();
  const OT::Sample       x   = OT::LHSExperiment(distribution, 60).generate();
  const Surrogate  surrogate = fit_surrogate(x, model(x), distribution, 4);
  const OT::Sample test      = distribution.getSample(2000);
  const auto       errors =
    held_out_errors(surrogate.model, test, model(test), surrogate.stated_error);
  // The function is smooth: the fit is good to a few thousandths of its
  // spread (about 0.25). The cross-validated error is never optimistic by
  // more than a factor of two; it may be pessimistic, as each fold's fit
  // has a tenth fewer points and kriging's error falls quickly with the
  // number of points, but not by more than a factor of four, and its 95 %
  // bound holds at least nine in ten new points.
  EXPECT_LT(errors.rms, 0.01) << surrogate.kind;
  EXPECT_EQ(surrogate.n_folds, 10u);
  EXPECT_GT(surrogate.cross_validation_rms, errors.rms / 2.);
  EXPECT_LT(surrogate.cross_validation_rms, errors.rms * 4.) << surrogate.kind;
  EXPECT_GT(errors.share_within_stated, 0.9);
}

TEST(Surrogate, RefusesMismatchedSamples)
{
  const OT::Distribution distribution = inputs();
  const OT::Sample       x            = distribution.getSample(10);
  EXPECT_THROW(fit_surrogate(x, OT::Sample(9, 1), distribution, 2),
               std::invalid_argument);
  EXPECT_THROW(
    fit_surrogate(distribution.getSample(4), OT::Sample(4, 1), distribution, 2),
    std::invalid_argument);
}

TEST(Surrogate, ChoosesKrigingWhereTheOutputHasAKink)
{
  // The smaller of two smooth branches, like two corners of which the
  // weaker governs: the slope jumps where they cross, which a polynomial
  // spreads over the whole space and kriging follows.
  const OT::SymbolicFunction kinked(
    OT::Description({"phi", "kn", "load"}),
    OT::Description({"min(0.03 * (phi - 30), 0.1 * log(kn / 9e9)) - "
                     "0.0005 * (load - 650)"}));
  OT::RandomGenerator::SetSeed(11);
  const OT::Distribution distribution = inputs();
  const OT::Sample       x   = OT::LHSExperiment(distribution, 80).generate();
  const Surrogate  surrogate = fit_surrogate(x, kinked(x), distribution, 4);
  const OT::Sample test      = distribution.getSample(2000);
  const auto       errors    = held_out_errors(surrogate.model,
                                      test,
                                      kinked(test),
                                      surrogate.stated_error);
  EXPECT_EQ(surrogate.chaos_degree, 0u) << surrogate.kind;
  // The stated error is a 95 % bound: of 2000 new points at least nine in
  // ten lie within it however the residuals are distributed.
  EXPECT_GT(errors.share_within_stated, 0.9);
  EXPECT_GT(surrogate.cross_validation_rms, errors.rms / 2.);
  EXPECT_LT(surrogate.cross_validation_rms, errors.rms * 2.) << surrogate.kind;
}
