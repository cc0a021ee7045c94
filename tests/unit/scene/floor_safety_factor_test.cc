// The chapter's route to the floor's safety factor: the rock mass's UCS
// sigma_ci s^a (Strength/) over Eq. 6.53's sigma_max, per mechanism.

#include <scene/closed_forms.h>

#include <gtest/gtest.h>

#include <cmath>

#include "default_scene.h"

using namespace FloorBlock;

// Default strength: sigma_ci = 40 MPa, GSI = 75, D = 0, so s = e^(-25/9)
// and a = 1/2 + (e^(-5) - e^(-20/3))/6 (Hoek et al. 2002, eqs. 3-4).
TEST(FloorSafetyFactor, MassStrengthOverEqSixFiftyThree)
{
  const auto   closed = Scene::evaluate_closed_forms(Testing::default_scene());
  const double s      = std::exp(-25. / 9.);
  const double a      = 0.5 + (std::exp(-5.) - std::exp(-20. / 3.)) / 6.;
  EXPECT_NEAR(closed.floor_strength, 40e6 * std::pow(s, a), 1e-3);
  unsigned int with_answer = 0;
  for (const auto &mechanism : closed.mechanisms)
    {
      const bool has_stress = mechanism.forces.status == Analytic::Status::ok &&
                              Analytic::has_contact_values(mechanism.contact.status);
      ASSERT_EQ(mechanism.floor_safety_factor.has_value(), has_stress)
        << Scene::to_string(mechanism.mechanism);
      if (!has_stress)
        continue;
      ++with_answer;
      EXPECT_NEAR(*mechanism.floor_safety_factor,
                  closed.floor_strength / mechanism.contact.max_stress,
                  1e-12);
    }
  // no_rotation at least: 9.95 MPa over 18.49 MPa.
  ASSERT_GE(with_answer, 1u);
  EXPECT_NEAR(*closed.mechanisms.front().floor_safety_factor, 0.538, 0.001);
}

// The strength scales the factor and nothing else.
TEST(FloorSafetyFactor, ProportionalToTheIntactStrength)
{
  const auto weak   = Scene::evaluate_closed_forms(
    Testing::default_scene({"Strength/Intact UCS=25e6"}));
  const auto strong = Scene::evaluate_closed_forms(
    Testing::default_scene({"Strength/Intact UCS=60e6"}));
  EXPECT_NEAR(*strong.mechanisms.front().floor_safety_factor /
                *weak.mechanisms.front().floor_safety_factor,
              60. / 25.,
              1e-12);
  EXPECT_DOUBLE_EQ(strong.mechanisms.front().contact.max_stress,
                   weak.mechanisms.front().contact.max_stress);
}

// Where Eq. 6.51 has no answer (the joint closes at its foot), no factor.
TEST(FloorSafetyFactor, NoneWithoutACornerStress)
{
  const auto closed = Scene::evaluate_closed_forms(Testing::default_scene(
    {"Bedding/Shape=planar", "Bedding/Inclination=-5"}));
  for (const auto &mechanism : closed.mechanisms)
    EXPECT_FALSE(mechanism.floor_safety_factor.has_value());
}
