// Inputs of each engine from the parsed scene: the closed forms' block chain
// (weights, support loads, inclinations), the face joint's floor lift, the
// Gmsh assembly and the contact law, against values worked out by hand
// from the scene entries.
#include <analytic/block_chain.h>
#include <common/units.h>
#include <contact/contact_problem.h>
#include <geometry/assembly_description.h>
#include <parameters/scenario_parameters.h>
#include <scene/analytic_inputs.h>
#include <scene/assembly_inputs.h>
#include <scene/contact_inputs.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
  using namespace FloorBlock;

  // Every expected value is a few operations on exact inputs: round-off only.
  constexpr double tolerance = 1e-12; // relative

  void
  expect_relative(const double actual, const double expected)
  {
    EXPECT_NEAR(actual, expected, tolerance * std::abs(expected))
      << "expected " << expected;
  }

  /** Four 1.5 m x 3 m blocks on a 10 degree plane, loaded next to the face. */
  Parameters::ScenarioParameters
  planar_scene(const std::string &loaded_blocks)
  {
    return Parameters::read_defaults("scene_inputs_test",
                                     {"Geometry/Number of blocks=4",
                                      "Geometry/Block width=1.5",
                                      "Geometry/Block height=3",
                                      "Geometry/Support width=2",
                                      "Material/Density=2000",
                                      "Loading/Gravity=10",
                                      "Loading/Support load=100",
                                      "Loading/Loaded blocks from face=" +
                                        loaded_blocks,
                                      "Bedding/Shape=planar",
                                      "Bedding/Inclination=10",
                                      "Joints/Bedding friction angle=35",
                                      "Joints/Vertical friction angle=25"});
  }

  // W_i = rho g L H = 2000 x 10 x 1.5 x 3 = 90 kN/m on every block; the
  // support's 100 t (980.665 kN) over the 2 loaded blocks and over b = 2 m
  // gives P = 245.16625 kN/m on blocks 4 and 3 (1st and 2nd from the face).
  TEST(SceneInputs, BlockChainOfAPlanarScene)
  {
    const auto                 scene = planar_scene("1,2");
    const Analytic::BlockChain chain = Scene::block_chain(scene);
    ASSERT_EQ(chain.n_blocks(), 4u);
    for (unsigned int i = 0; i < 4; ++i)
      {
        expect_relative(chain.weight[i], 90e3);
        expect_relative(chain.inclination[i], Units::degrees_to_radians(10.));
      }
    const double p = 100. * 1000. * 9.80665 / (2. * 2.);
    EXPECT_EQ(chain.support_load[0], 0.);
    EXPECT_EQ(chain.support_load[1], 0.);
    expect_relative(chain.support_load[2], p);
    expect_relative(chain.support_load[3], p);
    EXPECT_EQ(chain.block_width, 1.5);
    EXPECT_EQ(chain.block_height, 3.);
    expect_relative(chain.bedding_friction, Units::degrees_to_radians(35.));
    expect_relative(chain.vertical_friction, Units::degrees_to_radians(25.));
  }

  // The same total load over one block is twice as much per block; no
  // loaded block means no support load at all.
  TEST(SceneInputs, SupportLoadIsSharedByTheLoadedBlocksOnly)
  {
    const Analytic::BlockChain one = Scene::block_chain(planar_scene("3"));
    const std::vector<double>  expected_one{0.,
                                           100. * 1000. * 9.80665 / 2.,
                                           0.,
                                           0.};
    ASSERT_EQ(one.support_load.size(), 4u);
    for (unsigned int i = 0; i < 4; ++i)
      expect_relative(one.support_load[i], expected_one[i]);

    const Analytic::BlockChain none = Scene::block_chain(planar_scene(""));
    for (const double load : none.support_load)
      EXPECT_EQ(load, 0.);
  }

  // Planar bedding: the face joint closes by y = L tan(alpha) against the
  // upright face block.
  TEST(SceneInputs, FaceJointFloorLiftOfAPlanarScene)
  {
    const auto scene = planar_scene("1,2");
    expect_relative(Scene::face_joint_floor_lift(scene,
                                                 Scene::block_chain(scene)),
                    1.5 * std::tan(Units::degrees_to_radians(10.)));
  }

  // Parabola y = x^2/100, three 1 m blocks: block i's chord slope is
  // (2(n - i) + 1) L / k = 5/100, 3/100, 1/100; the face lift is
  // L tan(alpha_n) = L^2/k = 1 cm.
  TEST(SceneInputs, ParabolicInclinationsAndFaceLift)
  {
    const auto scene =
      Parameters::read_defaults("scene_inputs_test",
                                {"Geometry/Number of blocks=3",
                                 "Geometry/Block width=1",
                                 "Loading/Loaded blocks from face=1",
                                 "Bedding/Shape=parabolic",
                                 "Bedding/Curvature=100"});
    const Analytic::BlockChain chain = Scene::block_chain(scene);
    ASSERT_EQ(chain.inclination.size(), 3u);
    expect_relative(chain.inclination[0], std::atan(0.05));
    expect_relative(chain.inclination[1], std::atan(0.03));
    expect_relative(chain.inclination[2], std::atan(0.01));
    expect_relative(Scene::face_joint_floor_lift(scene, chain), 0.01);
  }

  // The Gmsh assembly takes the scene's geometry, bedding and mesh sizes.
  TEST(SceneInputs, AssemblyDescriptionCarriesGeometryBeddingAndMesh)
  {
    const auto scene =
      Parameters::read_defaults("scene_inputs_test",
                                {"Geometry/Number of blocks=5",
                                 "Geometry/Block width=1.2",
                                 "Geometry/Block height=2.5",
                                 "Geometry/Face block width=0.8",
                                 "Geometry/Base thickness=0.7",
                                 "Geometry/Corner rounding radius=0.03",
                                 "Loading/Loaded blocks from face=1,2",
                                 "Bedding/Shape=planar",
                                 "Bedding/Inclination=5",
                                 "Bedding/Floor uplift reading=inclined",
                                 "Mesh/Corner size=0.04",
                                 "Mesh/Far size=0.3",
                                 "Mesh/Growth rate=1.2"});
    const Geometry::AssemblyDescription description =
      Scene::assembly_description(scene);
    EXPECT_EQ(description.n_blocks, 5u);
    EXPECT_EQ(description.block_width, 1.2);
    EXPECT_EQ(description.block_height, 2.5);
    EXPECT_EQ(description.face_block_width, 0.8);
    EXPECT_EQ(description.base_thickness, 0.7);
    EXPECT_EQ(description.corner_rounding_radius, 0.03);
    EXPECT_EQ(description.bedding_shape, Geometry::BeddingShape::planar);
    expect_relative(description.inclination, Units::degrees_to_radians(5.));
    EXPECT_EQ(description.floor_uplift,
              Geometry::FloorUplift::inclined_bedding);
    EXPECT_EQ(description.mesh_corner_size, 0.04);
    EXPECT_EQ(description.mesh_far_size, 0.3);
    EXPECT_EQ(description.mesh_growth_rate, 1.2);
    EXPECT_TRUE(description.matching_joints);

    const auto lifted =
      Parameters::read_defaults("scene_inputs_test",
                                {"Bedding/Shape=parabolic",
                                 "Bedding/Floor uplift reading=lifted"});
    const auto lifted_description = Scene::assembly_description(lifted);
    EXPECT_EQ(lifted_description.bedding_shape,
              Geometry::BeddingShape::parabolic);
    EXPECT_EQ(lifted_description.floor_uplift,
              Geometry::FloorUplift::lifted_flat_bedding);
  }

  TEST(SceneInputs, ContactLawFollowsJointsLaw)
  {
    EXPECT_EQ(Scene::floor_problem_settings(
                Parameters::read_defaults("scene_inputs_test",
                                          {"Joints/Law=rigid"}))
                .law,
              Contact::JointLawKind::rigid);
    EXPECT_EQ(Scene::floor_problem_settings(
                Parameters::read_defaults("scene_inputs_test",
                                          {"Joints/Law=compliant"}))
                .law,
              Contact::JointLawKind::compliant);
  }
} // namespace
