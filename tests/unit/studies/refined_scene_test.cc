// What `run` and `converge` mean by a refined scene (studies/error_estimate,
// studies/convergence_ladder): the same scene meshed the same way, with
// every cell halved once more per level (Mesh/Global refinements).

#include <parameters/scenario_parameters.h>
#include <scene/mesh_sizing.h>

#include <gtest/gtest.h>
#include <studies/convergence_ladder.h>
#include <studies/error_estimate.h>

#include <string>

#include "default_scene.h"

using namespace FloorBlock;

using Testing::default_scene;

// The tool shall refine uniformly by halving every cell of the scene's own
// mesh once per level (nested meshes), the Gmsh sizes unchanged.
TEST(UniformLevelScene, AddsOneGlobalRefinementPerLevel)
{
  const auto scene = default_scene();
  // params/default.prm: compliant joints, so "auto" refines nothing.
  ASSERT_EQ(Scene::global_refinements(scene), 0u);

  const auto level_0 = Studies::uniform_level_scene(scene, 0);
  EXPECT_EQ(Scene::global_refinements(level_0), 0u);

  const auto level_2 = Studies::uniform_level_scene(scene, 2);
  EXPECT_EQ(Scene::global_refinements(level_2), 2u);
  // The Gmsh mesh and everything that is not the refinement count stay.
  EXPECT_EQ(level_2.mesh.corner_size, scene.mesh.corner_size);
  EXPECT_EQ(level_2.mesh.far_size, scene.mesh.far_size);
  EXPECT_EQ(level_2.mesh.growth_rate, scene.mesh.growth_rate);
  EXPECT_EQ(level_2.geometry.n_blocks, scene.geometry.n_blocks);
  EXPECT_EQ(level_2.loading.floor_lift, scene.loading.floor_lift);
  EXPECT_EQ(level_2.mesh.matching_joints, scene.mesh.matching_joints);
}

// A level counts from the scene's own refinements, "auto" included: the
// rigid law on the default scene starts one halving finer.
TEST(UniformLevelScene, CountsFromTheScenesOwnRefinements)
{
  auto scene       = default_scene();
  scene.joints.law = Contact::JointLawKind::rigid;
  ASSERT_EQ(Scene::global_refinements(scene), 1u);
  EXPECT_EQ(Scene::global_refinements(Studies::uniform_level_scene(scene, 2)),
            3u);
}

// The tool shall estimate `run`'s error against converge's uniform level 1,
// and refine the rigid-block model by doubling its points per joint.
TEST(RefinedScene, IsUniformLevelOneWithTwiceTheRigidPoints)
{
  const auto scene   = default_scene();
  const auto refined = Studies::refined_scene(scene);
  const auto level_1 = Studies::uniform_level_scene(scene, 1);
  EXPECT_EQ(refined.mesh.global_refinements, level_1.mesh.global_refinements);
  EXPECT_EQ(refined.mesh.corner_size, scene.mesh.corner_size);
  EXPECT_EQ(Scene::global_refinements(refined), 1u);
  EXPECT_EQ(refined.model.rigid_points_per_joint,
            2 * scene.model.rigid_points_per_joint);
}
