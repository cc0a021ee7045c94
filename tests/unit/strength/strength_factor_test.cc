// The strength factor of a stress state: principal stresses (compression
// positive) and strength over stress in each regime.

#include <strength/strength_factor.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace FloorBlock;

namespace
{
  const Strength::HoekBrownConstants mudstone =
    Strength::generalised_hoek_brown(4., 60., 0.);
  constexpr double sigma_ci = 25e6;
} // namespace

// A state rotated by 30 deg: the principal stresses come back, compression
// positive, sigma_zz included (here the smallest compression).
TEST(StrengthFactor, PrincipalStressesOfARotatedState)
{
  const double p = -12e6, q = -2e6, angle = M_PI / 6.; // tension positive
  const double c = std::cos(angle), s = std::sin(angle);
  const Strength::PlaneStrainStress stress{p * c * c + q * s * s,
                                           p * s * s + q * c * c,
                                           (p - q) * s * c,
                                           -1e6};
  const auto principal = Strength::principal_stresses(stress);
  EXPECT_NEAR(principal.sigma_1, 12e6, 1e-6);
  EXPECT_NEAR(principal.sigma_3, 1e6, 1e-6);
}

// Uniaxial compression at half the mass's UCS: FS = 2 (the chapter's
// route at a free surface: strength / stress).
TEST(StrengthFactor, UniaxialCompressionIsStrengthOverStress)
{
  const double ucs = Strength::uniaxial_compressive_strength(sigma_ci, mudstone);
  const double fs =
    Strength::strength_factor({0.5 * ucs, 0.}, sigma_ci, mudstone);
  EXPECT_NEAR(fs, 2., 1e-12);
}

// Confined: sigma_1f(sigma_3) / sigma_1.
TEST(StrengthFactor, ConfinementEntersThroughTheEnvelope)
{
  const double sigma_3 = 2e6, sigma_1 = 15e6;
  EXPECT_NEAR(Strength::strength_factor({sigma_1, sigma_3}, sigma_ci, mudstone),
              Strength::major_principal_strength(sigma_3, sigma_ci, mudstone) /
                sigma_1,
              1e-12);
}

// Tension beyond the tensile strength fails (FS < 1), with or without
// compression beside it; unloaded points get the cap, not infinity.
TEST(StrengthFactor, TensionAndTheUnloadedPoint)
{
  const double tension = Strength::tensile_strength(sigma_ci, mudstone);
  EXPECT_NEAR(
    Strength::strength_factor({5e6, -2. * tension}, sigma_ci, mudstone),
    0.5,
    1e-12);
  EXPECT_NEAR(
    Strength::strength_factor({-0.1 * tension, -0.5 * tension}, sigma_ci, mudstone),
    2.,
    1e-12);
  EXPECT_DOUBLE_EQ(Strength::strength_factor({0., 0.}, sigma_ci, mudstone),
                   Strength::largest_strength_factor);
}
