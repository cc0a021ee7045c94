// What `run` and `converge` mean by a refined scene (pipeline/error_estimate,
// pipeline/convergence_ladder): the same scene with every mesh size and the
// growth rate's excess over 1 scaled by 2^-level.

#include <parameters/scenario_parameters.h>
#include <pipeline/convergence_ladder.h>
#include <pipeline/error_estimate.h>

#include <gtest/gtest.h>

#include <string>

using namespace FloorBlock;

namespace
{
  Parameters::ScenarioParameters
  default_scene()
  {
    return Parameters::read_scenario(std::string(FLOORBLOCK_SOURCE_DIR) +
                                       "/params/default.prm",
                                     {});
  }

  /** Exact in binary: halving and subtracting 1 are exact here. */
  constexpr double exact = 1e-15;
} // namespace

// The tool shall refine uniformly by halving every mesh size and the growth
// rate's excess over 1, level by level.
TEST(UniformLevelScene, HalvesEverySizeAndTheGrowthExcessPerLevel)
{
  const auto scene = default_scene();
  // params/default.prm: Corner size 0.02 m, Far size 0.25 m, Growth 1.3.
  ASSERT_DOUBLE_EQ(scene.mesh.corner_size, 0.02);
  ASSERT_DOUBLE_EQ(scene.mesh.far_size, 0.25);
  ASSERT_DOUBLE_EQ(scene.mesh.growth_rate, 1.3);

  const auto level_0 = Pipeline::uniform_level_scene(scene, 0);
  EXPECT_EQ(level_0.mesh.corner_size, scene.mesh.corner_size);
  EXPECT_EQ(level_0.mesh.growth_rate, scene.mesh.growth_rate);

  const auto level_2 = Pipeline::uniform_level_scene(scene, 2);
  EXPECT_NEAR(level_2.mesh.corner_size, 0.005, exact);
  EXPECT_NEAR(level_2.mesh.far_size, 0.0625, exact);
  EXPECT_NEAR(level_2.mesh.growth_rate, 1.075, 4 * exact);
  // Everything that is not a mesh size stays.
  EXPECT_EQ(level_2.geometry.n_blocks, scene.geometry.n_blocks);
  EXPECT_EQ(level_2.loading.floor_lift, scene.loading.floor_lift);
  EXPECT_EQ(level_2.mesh.matching_joints, scene.mesh.matching_joints);
}

// The tool shall estimate `run`'s error against converge's uniform level 1,
// and refine the rigid-block model by doubling its points per joint.
TEST(RefinedScene, IsUniformLevelOneWithTwiceTheRigidPoints)
{
  const auto scene   = default_scene();
  const auto refined = Pipeline::refined_scene(scene);
  const auto level_1 = Pipeline::uniform_level_scene(scene, 1);
  EXPECT_EQ(refined.mesh.corner_size, level_1.mesh.corner_size);
  EXPECT_EQ(refined.mesh.far_size, level_1.mesh.far_size);
  EXPECT_EQ(refined.mesh.growth_rate, level_1.mesh.growth_rate);
  EXPECT_NEAR(refined.mesh.corner_size, 0.01, exact);
  EXPECT_NEAR(refined.mesh.growth_rate, 1.15, 4 * exact);
  EXPECT_EQ(refined.model.rigid_points_per_joint,
            2 * scene.model.rigid_points_per_joint);
}
