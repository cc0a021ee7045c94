// Barton-Bandis joint stiffness from joint data: the aperture estimate, the
// Bandis fits, the hyperbola's tangent stiffness and Barton's shear
// stiffness against hand-computed values and against the relations they
// come from.

#include <common/units.h>

#include <gtest/gtest.h>
#include <strength/barton_bandis.h>

#include <cmath>

using namespace FloorBlock;

namespace
{
  // A coal-measure joint: JRC 8, JCS 20 MPa, in a 40 MPa siltstone,
  // phi_r 25 deg; evaluated at sigma_n = 1 MPa on a 2 m joint.
  constexpr double intact_ucs     = 40e6; // Pa
  constexpr double normal_stress  = 1e6;  // Pa
  constexpr double sheared_length = 2.;   // m

  Strength::BartonBandisJoint
  coal_measure_joint()
  {
    return {8.,
            20e6,
            Strength::barton_initial_aperture(8., 20e6, intact_ucs),
            Units::degrees_to_radians(25.)};
  }
} // namespace

// a_j = JRC/5 (0.2 sigma_c/JCS - 0.1) mm = 8/5 (0.4 - 0.1) = 0.48 mm; a
// fresh joint (JCS = sigma_c) gets JRC/50 mm = 0.2 mm at JRC 10.
TEST(BartonBandis, InitialApertureFromRoughnessAndStrengths)
{
  EXPECT_NEAR(Strength::barton_initial_aperture(8., 20e6, 40e6),
              0.48e-3,
              1e-15);
  EXPECT_NEAR(Strength::barton_initial_aperture(10., 50e6, 50e6),
              0.2e-3,
              1e-15);
  EXPECT_LE(Strength::barton_initial_aperture(0., 20e6, 40e6), 0.);
  EXPECT_LT(Strength::barton_initial_aperture(8., 100e6, 40e6), 0.);
}

// By hand, JCS/a_j = 20/0.48 = 41.667 MPa/mm:
// K_ni = -7.15 + 1.75 x 8 + 0.02 x 41.667 = 7.6833 MPa/mm = 7.6833e9 Pa/m;
// V_m = -0.2960 - 0.0056 x 8 + 2.2410 x 41.667^-0.2450
//     = -0.3408 + 2.2410 x 0.40098 = 0.55786 mm.
// Five digits of the hand computation: within 1e-5 relative.
TEST(BartonBandis, BandisFitsOfTheCoalMeasureJoint)
{
  const auto joint = coal_measure_joint();
  EXPECT_NEAR(Strength::bandis_initial_normal_stiffness(joint) / 7.68333e9,
              1.,
              1e-5);
  EXPECT_NEAR(Strength::bandis_maximum_closure(joint) / 0.557856e-3, 1., 1e-5);
}

// K_n = K_ni (1 - sigma_n/(V_m K_ni + sigma_n))^-2 with V_m K_ni = 4.2862
// MPa: (1 - 1/5.2862)^-2 = 1.52104, K_n = 11.687 MPa/mm = 1.1687e10 Pa/m.
TEST(BartonBandis, NormalStiffnessAtOneMegapascal)
{
  const auto   joint   = coal_measure_joint();
  const double initial = Strength::bandis_initial_normal_stiffness(joint);
  const double closure = Strength::bandis_maximum_closure(joint);
  const double stiffness =
    Strength::hyperbolic_normal_stiffness(initial, closure, normal_stress);
  EXPECT_NEAR(stiffness / 1.168671e10, 1., 1e-5);
  // sigma_n = 0: the initial stiffness.
  EXPECT_DOUBLE_EQ(Strength::hyperbolic_normal_stiffness(initial, closure, 0.),
                   initial);
}

// The tangent stiffness is the slope of the closure curve: a central
// difference of sigma_n(Delta V) over the closure at sigma_n +- 1 kPa
// agrees to the difference's truncation error (relative 1e-6).
TEST(BartonBandis, NormalStiffnessIsTheSlopeOfTheClosureCurve)
{
  const auto   joint   = coal_measure_joint();
  const double initial = Strength::bandis_initial_normal_stiffness(joint);
  const double closure = Strength::bandis_maximum_closure(joint);
  for (const double stress : {0.2e6, 1e6, 5e6})
    {
      const double step = 1e3; // Pa
      const double below =
        Strength::hyperbolic_closure(initial, closure, stress - step);
      const double above =
        Strength::hyperbolic_closure(initial, closure, stress + step);
      EXPECT_NEAR(2. * step / (above - below) /
                    Strength::hyperbolic_normal_stiffness(initial,
                                                          closure,
                                                          stress),
                  1.,
                  1e-6)
        << stress;
      EXPECT_LT(Strength::hyperbolic_closure(initial, closure, stress),
                closure);
    }
}

// phi_peak = 8 log10(20) + 25 = 35.408 deg; K_s = (100 / 2 m) x 1 MPa x
// tan(35.408 deg) = 35.544 MPa/m = 3.5544e7 Pa/m.
TEST(BartonBandis, ShearStiffnessOfTheCoalMeasureJoint)
{
  const auto joint = coal_measure_joint();
  EXPECT_NEAR(Units::radians_to_degrees(
                Strength::barton_peak_friction_angle(joint, normal_stress)),
              35.40824,
              1e-5);
  EXPECT_NEAR(Strength::barton_shear_stiffness(joint,
                                               normal_stress,
                                               sheared_length) /
                3.554397e7,
              1.,
              1e-6);
}

// A smooth joint (JRC 0) keeps phi_r at any stress, and K_s is the
// residual strength over 1 % of the sheared length; at sigma_n = JCS the
// roughness term vanishes too.
TEST(BartonBandis, SmoothJointAndStressAtWallStrength)
{
  auto joint                  = coal_measure_joint();
  joint.roughness_coefficient = 0.;
  EXPECT_DOUBLE_EQ(Strength::barton_peak_friction_angle(joint, 3e6),
                   joint.residual_friction_angle);
  EXPECT_NEAR(Strength::barton_shear_stiffness(joint, 3e6, 1.),
              100. * 3e6 * std::tan(joint.residual_friction_angle),
              1e-6);
  const auto rough = coal_measure_joint();
  EXPECT_NEAR(Strength::barton_peak_friction_angle(rough, rough.wall_strength),
              rough.residual_friction_angle,
              1e-15);
}

// The apertures where the fits end: K_ni = 0 at the largest (a smooth
// joint; JRC 2, JCS 20 MPa: 0.02 x 20 / (7.15 - 3.5) = 0.10959 mm), V_m = 0
// at the smallest (JRC 20: -0.408 + 2.2410 (JCS/a_j)^-0.245 = 0).
TEST(BartonBandis, AperturesWhereTheFitsEnd)
{
  const double largest =
    Strength::bandis_largest_aperture_for_stiffness(2., 20e6);
  EXPECT_NEAR(largest, 0.4 / 3.65 * 1e-3, 1e-15);
  Strength::BartonBandisJoint joint{2., 20e6, largest, 0.};
  EXPECT_NEAR(Strength::bandis_initial_normal_stiffness(joint), 0., 1e-3);
  EXPECT_TRUE(
    std::isinf(Strength::bandis_largest_aperture_for_stiffness(8., 20e6)));

  joint.roughness_coefficient = 20.;
  joint.wall_strength         = 100e6;
  joint.initial_aperture =
    Strength::bandis_smallest_aperture_for_closure(20., 100e6);
  EXPECT_NEAR(Strength::bandis_maximum_closure(joint), 0., 1e-15);
  joint.initial_aperture *= 1.01;
  EXPECT_GT(Strength::bandis_maximum_closure(joint), 0.);
}
