// The closed forms in the scene's frame: the chapter's alpha per block of a
// planar, curved and dipping bed against hand-derived values, the face
// joint's y (independent of the dip), and the scenes the closed forms do
// not describe.
#include <analytic/block_chain.h>
#include <common/units.h>
#include <parameters/scenario_parameters.h>
#include <scene/analytic_inputs.h>
#include <scene/closed_forms.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
  using namespace FloorBlock;
  using Units::degrees_to_radians;

  constexpr double frame_tolerance = 1e-12; // relative: a few operations

  void
  expect_frame_value(const double actual, const double expected)
  {
    EXPECT_NEAR(actual, expected, frame_tolerance * std::abs(expected))
      << "expected " << expected;
  }

  Parameters::ScenarioParameters
  scene_with(const std::vector<std::string> &entries)
  {
    return Parameters::read_defaults("scene_frame_test", entries);
  }

  // A frame turned by delta: a bed level in the frame falls away from the
  // face by delta; one rising by beta in the frame rises by beta - delta.
  TEST(TrueInclination, IsTheFrameInclinationLessTheDip)
  {
    expect_frame_value(Scene::true_inclination(0., degrees_to_radians(10.)),
                       degrees_to_radians(-10.));
    expect_frame_value(Scene::true_inclination(degrees_to_radians(10.),
                                               degrees_to_radians(15.)),
                       degrees_to_radians(-5.));
    EXPECT_EQ(Scene::true_inclination(degrees_to_radians(7.), 0.),
              degrees_to_radians(7.));
  }

  // Planar bed rising 10 deg in a frame dipping 15 deg: alpha = -5 deg on
  // every block.
  TEST(SceneFrame, PlanarBedInADippingFrame)
  {
    const auto chain =
      Scene::block_chain(scene_with({"Geometry/Number of blocks=4",
                                     "Loading/Loaded blocks from face=1",
                                     "Bedding/Shape=planar",
                                     "Bedding/Inclination=10",
                                     "Bedding/Frame dip=15",
                                     "Bedding/Floor uplift reading=inclined",
                                     "Loading/Uplift mode=vertical",
                                     "Loading/Floor lift=0.01"}));
    ASSERT_EQ(chain.inclination.size(), 4u);
    for (const double alpha : chain.inclination)
      expect_frame_value(alpha, degrees_to_radians(-5.));
  }

  // Parabola y = x^2/100 of three 1 m blocks in a frame dipping 10 deg:
  // chord slopes 5/100, 3/100, 1/100 in the frame (block 1 at the free end
  // first), each less 10 deg; the face lift stays L tan(atan(0.01)) =
  // 1 cm, since the face block turns with the frame.
  TEST(SceneFrame, CurvedBedInADippingFrame)
  {
    const std::vector<std::string> curved = {
      "Geometry/Number of blocks=3",
      "Geometry/Block width=1",
      "Loading/Loaded blocks from face=1",
      "Bedding/Shape=parabolic",
      "Bedding/Curvature=100"};
    auto dipping = curved;
    dipping.push_back("Bedding/Frame dip=10");
    const auto scene = scene_with(dipping);
    const auto chain = Scene::block_chain(scene);
    ASSERT_EQ(chain.inclination.size(), 3u);
    const double dip = degrees_to_radians(10.);
    expect_frame_value(chain.inclination[0], std::atan(0.05) - dip);
    expect_frame_value(chain.inclination[1], std::atan(0.03) - dip);
    expect_frame_value(chain.inclination[2], std::atan(0.01) - dip);
    expect_frame_value(Scene::face_joint_floor_lift(scene, chain), 0.01);

    const auto level = scene_with(curved);
    expect_frame_value(Scene::face_joint_floor_lift(scene, chain),
                       Scene::face_joint_floor_lift(level,
                                                    Scene::block_chain(level)));
  }

  TEST(SceneDifferences, TheChaptersSetUpsAreTheSameScene)
  {
    // The default scene: a flat mesh bent into its parabola by the lift.
    EXPECT_TRUE(Scene::scene_differences(scene_with({})).empty());
    // A level bed moved along itself in a dipping frame (S6's motion).
    EXPECT_TRUE(Scene::scene_differences(
                  scene_with({"Bedding/Shape=planar",
                              "Bedding/Inclination=0",
                              "Bedding/Frame dip=10",
                              "Loading/Uplift mode=dip toward face",
                              "Loading/Floor lift=0.01"}))
                  .empty());
    // The inclined reading: the blocks stand on the bedding from the start.
    EXPECT_TRUE(Scene::scene_differences(
                  scene_with({"Bedding/Floor uplift reading=inclined",
                              "Loading/Uplift mode=vertical",
                              "Loading/Floor lift=0.05"}))
                  .empty());
  }

  TEST(SceneDifferences, AnotherBedOrANonVerticalLoadIsAnotherScene)
  {
    // A flat mesh raised straight up under an inclined bedding.
    EXPECT_EQ(Scene::scene_differences(
                scene_with({"Bedding/Shape=planar",
                            "Bedding/Inclination=5",
                            "Loading/Uplift mode=vertical",
                            "Loading/Floor lift=0.05"}))
                .size(),
              1u);
    // A level bed tilted by the uplift.
    EXPECT_EQ(Scene::scene_differences(scene_with({"Bedding/Shape=planar",
                                                   "Bedding/Inclination=0",
                                                   "Loading/Uplift mode=tilt",
                                                   "Loading/Floor lift=0.05"}))
                .size(),
              1u);
    // The parabola bent to half the bedding's rise.
    EXPECT_EQ(Scene::scene_differences(
                scene_with({"Geometry/Number of blocks=6",
                            "Geometry/Block width=1",
                            "Bedding/Curvature=400",
                            "Loading/Floor lift=0.045",
                            "Loading/Floor lift against bedding=may differ"}))
                .size(),
              1u);
    // A support load normal to block tops in a dipping frame; without a
    // support load the direction does not matter.
    const std::vector<std::string> normal_in_dipping_frame = {
      "Bedding/Shape=planar",
      "Bedding/Inclination=0",
      "Bedding/Frame dip=10",
      "Loading/Uplift mode=dip toward face",
      "Loading/Floor lift=0.01",
      "Loading/Support load direction=normal to block top"};
    EXPECT_EQ(
      Scene::scene_differences(scene_with(normal_in_dipping_frame)).size(), 1u);
    auto unloaded = normal_in_dipping_frame;
    unloaded.push_back("Loading/Support load=0");
    EXPECT_TRUE(Scene::scene_differences(scene_with(unloaded)).empty());
  }
} // namespace
