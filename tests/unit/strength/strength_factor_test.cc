// The strength factor of a stress state: principal stresses (compression
// positive) and the factor that scales the state onto the Hoek-Brown
// envelope.

#include <gtest/gtest.h>
#include <strength/strength_factor.h>

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
  const double ucs =
    Strength::uniaxial_compressive_strength(sigma_ci, mudstone);
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

// The factor is the smallest scaling that reaches the envelope, and the
// scaled path is inside below it and outside above it: checked on a dense
// geometric grid of k for states from biaxial tension to high confinement
// (the bisection relies on the path crossing the envelope once).
TEST(StrengthFactor, OneCrossingInsideBelowOutsideAbove)
{
  const auto outside = [](const double k, const double s1, const double s3) {
    return k * s1 >=
           Strength::major_principal_strength(k * s3, sigma_ci, mudstone);
  };
  unsigned int n_states = 0;
  for (double sigma_1 = -1e6; sigma_1 <= 61e6; sigma_1 += 2e6)
    for (double sigma_3 = -3e6; sigma_3 <= sigma_1; sigma_3 += 0.5e6)
      {
        const double k =
          Strength::strength_factor({sigma_1, sigma_3}, sigma_ci, mudstone);
        ASSERT_TRUE(std::isfinite(k) && k > 0.);
        for (double q = 1e-4; q <= Strength::largest_strength_factor; q *= 1.02)
          {
            if (q < k * (1. - 1e-9))
              EXPECT_FALSE(outside(q, sigma_1, sigma_3))
                << sigma_1 << ", " << sigma_3 << ": k " << k << ", q " << q;
            else if (q > k * (1. + 1e-9))
              EXPECT_TRUE(outside(q, sigma_1, sigma_3))
                << sigma_1 << ", " << sigma_3 << ": k " << k << ", q " << q;
          }
        ++n_states;
      }
  EXPECT_GT(n_states, 1000u);
}

// A stress far beyond the strength (k below 1e-4): still the crossing.
TEST(StrengthFactor, FactorBelowTheScanStartIsStillOnTheEnvelope)
{
  const double sigma_1 = 1e6 * sigma_ci;
  const double k = Strength::strength_factor({sigma_1, 0.}, sigma_ci, mudstone);
  EXPECT_NEAR(k * sigma_1,
              Strength::uniaxial_compressive_strength(sigma_ci, mudstone),
              1e-9 * sigma_ci);
}
