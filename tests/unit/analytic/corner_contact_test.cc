// The tool shall estimate corner contact area and stress (6.51-6.53).

#include <analytic/corner_contact.h>

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

using namespace FloorBlock::Analytic;

namespace
{
  // Hand example: Q = 1.5 MN over b = 1.5 m, y = 2.5 mm, E = 16 GPa, L = 1 m.
  // 2 Q / (y E b) = 3e6 / (0.0025 * 16e9 * 1.5) = 0.05, so
  // c = L sqrt(0.05) = 0.2236068 m, A = b c = 0.3354102 m^2,
  // sigma_avg = Q / A = 4.472136 MPa, sigma_max = sqrt(2 y E Q / (b L^2))
  // = sqrt(8e13) Pa = 8.944272 MPa.
  constexpr double force = 1.5e6, lift = 2.5e-3, modulus = 16.e9;
  constexpr double support_width = 1.5, width = 1., height = 2.;
  constexpr double hand_tolerance = 1e-6; // hand values carry 7 digits
} // namespace

TEST(CornerContact, ShallReproduceTheHandComputedExample)
{
  const CornerContact contact =
    corner_contact(force, lift, modulus, support_width, width, height);
  EXPECT_EQ(contact.status, Status::ok);
  EXPECT_NEAR(contact.contact_length, 0.2236068, hand_tolerance);
  EXPECT_NEAR(contact.contact_area, 0.3354102, hand_tolerance);
  EXPECT_NEAR(contact.average_stress / 1e6, 4.472136, hand_tolerance);
  EXPECT_NEAR(contact.max_stress / 1e6, 8.944272, hand_tolerance);
}

TEST(CornerContact,
     ShallSatisfyEquilibriumAndCompatibilityOfTheTriangularStress)
{
  const CornerContact contact =
    corner_contact(force, lift, modulus, support_width, width, height);
  // Equilibrium: the triangle of height sigma_max over c carries Q.
  EXPECT_NEAR(0.5 * contact.max_stress * contact.contact_length *
                support_width / force,
              1.,
              1e-12);
  // Compatibility: sigma_max = E * overlap / L, overlap = (y / L) c.
  EXPECT_NEAR(modulus * (lift / width) * contact.contact_length / width /
                contact.max_stress,
              1.,
              1e-12);
}

TEST(CornerContact, ShallScaleStressWithTheRootOfForceLiftAndModulus)
{
  const CornerContact base =
    corner_contact(force, lift, modulus, support_width, width, height);
  const CornerContact four_times_force =
    corner_contact(4. * force, lift, modulus, support_width, width, height);
  const CornerContact four_times_lift =
    corner_contact(force, 4. * lift, modulus, support_width, width, height);
  EXPECT_NEAR(four_times_force.max_stress / base.max_stress, 2., 1e-12);
  EXPECT_NEAR(four_times_force.contact_area / base.contact_area, 2., 1e-12);
  EXPECT_NEAR(four_times_lift.max_stress / base.max_stress, 2., 1e-12);
  EXPECT_NEAR(four_times_lift.contact_area / base.contact_area, 0.5, 1e-12);
}

// The hand example's y* = 2 Q L^2 / (E b H^2) = 3e6 / (16e9 x 1.5 x 4)
// = 3.125e-5 m: below it in magnitude the whole joint face is in contact.
constexpr double whole_joint_lift = 3.125e-5;

// y = 0: no rotation, a uniform closure: sigma = Q / (b H) = 0.5 MPa over
// A = b H = 3 m^2. y = +-1e-5 m adds E |y| H / (2 L^2) = 0.16 MPa at floor
// level (y > 0) or at the foot (y < 0).
TEST(CornerContact, ShallPutTheWholeJointInContactForASmallRelativeRotation)
{
  for (const double small_lift : {0., 1e-5, -1e-5})
    {
      const CornerContact contact = corner_contact(
        force, small_lift, modulus, support_width, width, height);
      EXPECT_EQ(contact.status, Status::whole_joint_in_contact) << small_lift;
      EXPECT_EQ(contact.contact_length, height);
      EXPECT_NEAR(contact.contact_area, 3., 1e-12);
      EXPECT_NEAR(contact.average_stress, 0.5e6, 1e-12 * 0.5e6);
      EXPECT_NEAR(contact.max_stress,
                  small_lift == 0. ? 0.5e6 : 0.66e6,
                  1e-12 * 0.66e6)
        << small_lift;
    }
}

// At y = y* the triangle of 6.51 just reaches the foot: both regimes give
// c = H and sigma_max = 2 Q / (b H) = 1 MPa.
TEST(CornerContact, ShallBeContinuousWhereTheTriangleReachesTheFoot)
{
  const CornerContact whole = corner_contact(
    force, whole_joint_lift, modulus, support_width, width, height);
  const CornerContact triangle = corner_contact(force,
                                                whole_joint_lift * (1. + 1e-9),
                                                modulus,
                                                support_width,
                                                width,
                                                height);
  EXPECT_EQ(whole.status, Status::whole_joint_in_contact);
  EXPECT_EQ(triangle.status, Status::ok);
  EXPECT_NEAR(whole.max_stress, 1e6, 1e-9 * 1e6);
  EXPECT_NEAR(triangle.max_stress, 1e6, 1e-8 * 1e6);
  EXPECT_NEAR(triangle.contact_length, height, 1e-8 * height);
}

// y < -y*: the joint closes at its foot; no force with y <= 0: nothing
// touches at floor level. Neither has a floor-level corner contact.
TEST(CornerContact, ShallReportZeroFloorLiftWhereTheFloorLevelCornerIsOpen)
{
  for (const auto &[q, y] : {std::pair<double, double>{force, -1e-3},
                             std::pair<double, double>{0., 0.}})
    {
      const CornerContact contact =
        corner_contact(q, y, modulus, support_width, width, height);
      EXPECT_EQ(contact.status, Status::zero_floor_lift);
      EXPECT_EQ(contact.contact_area, 0.);
      EXPECT_EQ(contact.max_stress, 0.);
    }
}

TEST(CornerContact, ShallGiveZeroStressForZeroForceAndRejectBadInput)
{
  const CornerContact unloaded =
    corner_contact(0., lift, modulus, support_width, width, height);
  EXPECT_EQ(unloaded.status, Status::ok);
  EXPECT_EQ(unloaded.max_stress, 0.);
  EXPECT_EQ(
    corner_contact(-1., lift, modulus, support_width, width, height).status,
    Status::invalid_input);
  EXPECT_EQ(
    corner_contact(force, lift, 0., support_width, width, height).status,
    Status::invalid_input);
  EXPECT_EQ(
    corner_contact(force, std::nan(""), modulus, support_width, width, height)
      .status,
    Status::invalid_input);
}
