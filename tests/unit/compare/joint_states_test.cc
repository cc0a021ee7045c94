// The FEM's joints against their friction limits (compare/joint_states.h),
// on hand-made increments: which joints slip, which beds are open, how far
// the slip chain holds, and which mechanisms assume those states.
#include <analytic/block_chain.h>
#include <compare/joint_states.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace FloorBlock;

namespace
{
  // phi_v = 10 deg, phi_h = 30 deg on three blocks.
  Scene::ClosedForms
  three_block_chain()
  {
    Scene::ClosedForms forms;
    forms.chain = Analytic::uniform_chain(
      3, 40e3, 0., 0., 1., 2., 30. * M_PI / 180., 10. * M_PI / 180.);
    return forms;
  }

  /** A joint carrying N with V = use x N tan(angle). */
  Contact::JointReport
  loaded_joint(const std::string &name,
               const double       normal_force,
               const double       use,
               const double       angle_degrees)
  {
    Contact::JointReport report;
    report.name         = name;
    report.normal_force = normal_force;
    report.shear_force =
      -use * normal_force * std::tan(angle_degrees * M_PI / 180.);
    return report;
  }
} // namespace

// Every bed slips; vertical joints 1 and 2 slip, 3 does not: the slip
// chain holds up to joint 2, and no mechanism assumes the whole state.
TEST(JointStates, SlipChainHoldsUpToTheFirstJointBelowItsLimit)
{
  Contact::IncrementResult increment;
  increment.joints  = {loaded_joint("vertical 1", 1e5, 1., 10.),
                       loaded_joint("vertical 2", 2e5, 1., 10.),
                       loaded_joint("vertical 3", 3e5, 0.4, 10.),
                       loaded_joint("bedding 1", 5e4, 1., 30.),
                       loaded_joint("bedding 2", 5e4, 1., 30.),
                       loaded_joint("bedding 3", 5e4, 1., 30.)};
  const auto states = Compare::joint_states(increment, three_block_chain());
  ASSERT_EQ(states.vertical_use.size(), 3u);
  EXPECT_NEAR(states.vertical_use[0], 1., 1e-12);
  EXPECT_NEAR(states.vertical_use[2], 0.4, 1e-12);
  EXPECT_NEAR(states.bedding_use[1], 1., 1e-12);
  EXPECT_TRUE(states.open_beds.empty());
  EXPECT_EQ(states.slip_chain_holds, std::vector<bool>({true, true, false}));
  EXPECT_TRUE(states.holding.empty());
}

// Beds slip and every vertical joint sticks: rotation_no_vertical_slip's
// assumption. With every joint at its limit, both slip mechanisms'.
TEST(JointStates, MechanismsAssumingTheStatesAreNamed)
{
  Contact::IncrementResult sticking;
  sticking.joints = {loaded_joint("vertical 1", 1e5, 0.5, 10.),
                     loaded_joint("vertical 2", 2e5, 0.2, 10.),
                     loaded_joint("vertical 3", 3e5, 0.1, 10.),
                     loaded_joint("bedding 1", 5e4, 1., 30.),
                     loaded_joint("bedding 2", 5e4, 1., 30.),
                     loaded_joint("bedding 3", 5e4, 1., 30.)};
  EXPECT_EQ(Compare::joint_states(sticking, three_block_chain()).holding,
            std::vector<Scene::Mechanism>(
              {Scene::Mechanism::rotation_no_vertical_slip}));

  Contact::IncrementResult slipping = sticking;
  for (unsigned int j = 0; j < 3; ++j)
    slipping.joints[j] = loaded_joint(slipping.joints[j].name,
                                      slipping.joints[j].normal_force,
                                      1.,
                                      10.);
  EXPECT_EQ(Compare::joint_states(slipping, three_block_chain()).holding,
            std::vector<Scene::Mechanism>(
              {Scene::Mechanism::no_rotation,
               Scene::Mechanism::rotation_vertical_slip}));
}

// A bed without normal force is open, counts as not slipping, and is
// named; then no mechanism (all stand the blocks on their beds) holds.
TEST(JointStates, OpenBedsAreNamedAndHoldNoMechanism)
{
  Contact::IncrementResult increment;
  increment.joints  = {loaded_joint("vertical 1", 1e5, 1., 10.),
                       loaded_joint("vertical 2", 2e5, 1., 10.),
                       loaded_joint("vertical 3", 3e5, 1., 10.),
                       loaded_joint("bedding 1", 5e4, 1., 30.),
                       loaded_joint("bedding 2", 0., 0., 30.),
                       loaded_joint("bedding 3", 0., 0., 30.)};
  const auto states = Compare::joint_states(increment, three_block_chain());
  EXPECT_EQ(states.open_beds, std::vector<unsigned int>({2, 3}));
  EXPECT_EQ(states.bedding_use[1], 0.);
  EXPECT_EQ(states.slip_chain_holds, std::vector<bool>({true, false, false}));
  EXPECT_TRUE(states.holding.empty());
  EXPECT_NE(states.text.find("beds 2, 3 open"), std::string::npos)
    << states.text;
}
