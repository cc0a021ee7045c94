// The strength factor of a stress state: principal stresses (compression
// positive) and the factor that scales the state onto the Hoek-Brown
// envelope.

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
  EXPECT_NEAR(Strength::strength_factor({0.5 * ucs, 0.}, sigma_ci, mudstone),
              2.,
              1e-9);
}

// Equal biaxial tension: FS = sigma_t / |sigma_3|, the criterion's own
// tensile strength s sigma_ci / m_b.
TEST(StrengthFactor, BiaxialTensionIsTensileStrengthOverTension)
{
  const double tension = Strength::tensile_strength(sigma_ci, mudstone);
  EXPECT_NEAR(Strength::strength_factor({-0.25 * tension, -0.25 * tension},
                                        sigma_ci,
                                        mudstone),
              4.,
              1e-9);
}

// Any state: k sigma lies on the envelope, k sigma_1 = sigma_1f(k sigma_3),
// and slightly less scaling stays inside.
TEST(StrengthFactor, ScalesTheStateOntoTheEnvelope)
{
  for (const auto &[sigma_1, sigma_3] : {std::pair{15e6, 2e6},
                                         std::pair{11e6, -0.6e6},
                                         std::pair{3e6, -0.2e6},
                                         std::pair{40e6, 10e6}})
    {
      const double k =
        Strength::strength_factor({sigma_1, sigma_3}, sigma_ci, mudstone);
      ASSERT_LT(k, Strength::largest_strength_factor);
      EXPECT_NEAR(k * sigma_1,
                  Strength::major_principal_strength(k * sigma_3,
                                                     sigma_ci,
                                                     mudstone),
                  1e-6 * sigma_ci)
        << sigma_1 << ", " << sigma_3;
      EXPECT_LT(0.999 * k * sigma_1,
                Strength::major_principal_strength(0.999 * k * sigma_3,
                                                   sigma_ci,
                                                   mudstone));
    }
}

// Continuous through the tensile strength: sigma_3 just above and just
// below -sigma_t under the same sigma_1 give nearly the same factor.
TEST(StrengthFactor, ContinuousThroughTheTensileStrength)
{
  const double tension = Strength::tensile_strength(sigma_ci, mudstone);
  const double above =
    Strength::strength_factor({5e6, -0.999 * tension}, sigma_ci, mudstone);
  const double below =
    Strength::strength_factor({5e6, -1.001 * tension}, sigma_ci, mudstone);
  EXPECT_NEAR(above, below, 0.01 * above);
  EXPECT_LT(below, 1.);
}

// Unloaded points get the cap, not infinity.
TEST(StrengthFactor, UnloadedPointGetsTheCap)
{
  EXPECT_DOUBLE_EQ(Strength::strength_factor({0., 0.}, sigma_ci, mudstone),
                   Strength::largest_strength_factor);
}
