// The tool shall estimate corner contact area and stress (6.51-6.53).

#include <analytic/corner_contact.h>

#include <gtest/gtest.h>

#include <cmath>

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

TEST(CornerContact, ShallReportZeroFloorLiftInsteadOfAnInfiniteArea)
{
  for (const double no_lift : {0., -1e-3})
    {
      const CornerContact contact =
        corner_contact(force, no_lift, modulus, support_width, width, height);
      EXPECT_EQ(contact.status, Status::zero_floor_lift);
      EXPECT_TRUE(std::isfinite(contact.contact_area));
      EXPECT_TRUE(std::isfinite(contact.max_stress));
    }
}

TEST(CornerContact, ShallReportAContactLongerThanTheBlock)
{
  const CornerContact contact =
    corner_contact(force, 1e-9, modulus, support_width, width, height);
  EXPECT_EQ(contact.status, Status::contact_longer_than_block);
  EXPECT_GT(contact.contact_length, height);
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
