// Generalised Hoek-Brown (2002 edition): m_b, s, a against published values
// and the intact-rock limit; the strength curve and its two end points.

#include <common/input_error.h>
#include <strength/hoek_brown.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace FloorBlock;

// RocLab's (and Hoek, Carranza-Torres and Corkum 2002's) worked rock mass:
// GSI = 50, m_i = 10, D = 0 gives m_b = 1.677, s = 0.0039, a = 0.506, as
// printed (3-4 digits: within 1 %).
TEST(HoekBrown, PublishedConstantsForGsiFiftyMiTen)
{
  const auto constants = Strength::generalised_hoek_brown(10., 50., 0.);
  EXPECT_NEAR(constants.m_b / 1.677, 1., 0.01);
  EXPECT_NEAR(constants.s / 0.0039, 1., 0.01);
  EXPECT_NEAR(constants.a / 0.506, 1., 0.01);
}

// The same against the 2002 formulas to round-off, with a disturbed mass
// (D = 0.7, blasting damage): every constant drops.
TEST(HoekBrown, DisturbanceWeakensTheMass)
{
  const auto undisturbed = Strength::generalised_hoek_brown(7., 60., 0.);
  const auto disturbed   = Strength::generalised_hoek_brown(7., 60., 0.7);
  EXPECT_NEAR(undisturbed.m_b, 7. * std::exp(-40. / 28.), 1e-12);
  EXPECT_NEAR(disturbed.m_b, 7. * std::exp(-40. / 18.2), 1e-12);
  EXPECT_NEAR(disturbed.s, std::exp(-40. / 6.9), 1e-15);
  EXPECT_LT(disturbed.m_b, undisturbed.m_b);
  EXPECT_LT(disturbed.s, undisturbed.s);
  EXPECT_DOUBLE_EQ(disturbed.a, undisturbed.a); // a depends on GSI only
}

// GSI = 100: intact rock, the 1980 criterion sigma_1 = sigma_3 +
// sqrt(m sigma_ci sigma_3 + sigma_ci^2); UCS sigma_ci, tensile sigma_ci/m_i.
TEST(HoekBrown, GsiHundredIsIntactRock)
{
  const double sigma_ci  = 40e6;
  const auto   constants = Strength::generalised_hoek_brown(7., 100., 0.3);
  EXPECT_NEAR(constants.m_b, 7., 1e-12);
  EXPECT_NEAR(constants.s, 1., 1e-15);
  EXPECT_NEAR(constants.a, 0.5, 1e-15);
  EXPECT_NEAR(Strength::uniaxial_compressive_strength(sigma_ci, constants),
              sigma_ci,
              1e-6);
  EXPECT_NEAR(Strength::tensile_strength(sigma_ci, constants),
              sigma_ci / 7.,
              1e-6);
  const double sigma_3 = 5e6;
  EXPECT_NEAR(Strength::major_principal_strength(sigma_3, sigma_ci, constants),
              sigma_3 + std::sqrt(7. * sigma_ci * sigma_3 +
                                  sigma_ci * sigma_ci),
              1e-6);
}

// At the tensile strength the envelope meets sigma_1 = sigma_3; beyond it
// the rock carries nothing more than the tension itself.
TEST(HoekBrown, EnvelopeEndsAtTheTensileStrength)
{
  const double sigma_ci  = 25e6;
  const auto   constants = Strength::generalised_hoek_brown(4., 50., 0.);
  const double tension   = Strength::tensile_strength(sigma_ci, constants);
  EXPECT_NEAR(
    Strength::major_principal_strength(-tension, sigma_ci, constants),
    -tension,
    1e-9 * sigma_ci);
  EXPECT_DOUBLE_EQ(
    Strength::major_principal_strength(-2. * tension, sigma_ci, constants),
    -2. * tension);
  // Confinement strengthens.
  EXPECT_GT(Strength::major_principal_strength(1e6, sigma_ci, constants),
            Strength::major_principal_strength(0., sigma_ci, constants) +
              1e6);
}

TEST(HoekBrown, RefusesConstantsOutsideTheirRanges)
{
  EXPECT_THROW(Strength::generalised_hoek_brown(0., 50., 0.), InputError);
  EXPECT_THROW(Strength::generalised_hoek_brown(-3., 50., 0.), InputError);
  EXPECT_THROW(Strength::generalised_hoek_brown(7., 9., 0.), InputError);
  EXPECT_THROW(Strength::generalised_hoek_brown(7., 101., 0.), InputError);
  EXPECT_THROW(Strength::generalised_hoek_brown(7., 50., 1.2), InputError);
  EXPECT_THROW(Strength::generalised_hoek_brown(7., NAN, 0.), InputError);
}
