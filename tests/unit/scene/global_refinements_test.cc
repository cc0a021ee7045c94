// Scene::global_refinements: "auto" refines the whole mesh only where the
// corner fillet, not the joint springs, limits the contact concentration.

#include <parameters/scenario_parameters.h>
#include <scene/mesh_sizing.h>

#include <gtest/gtest.h>

#include <string>

#include "default_scene.h"

using namespace FloorBlock;

using Testing::default_scene;

// E/kn of Table 6.1: E = 9KG/(3K+G) = 16.09 GPa over kn = 9e9 Pa/m.
TEST(JointComplianceLength, IsYoungsModulusOverNormalStiffness)
{
  auto scene = default_scene();
  EXPECT_NEAR(Scene::joint_compliance_length(scene),
              9. * 9e9 * 6.7e9 / (3. * 9e9 + 6.7e9) / 9e9,
              1e-12);
  scene.joints.law = Contact::JointLawKind::rigid;
  EXPECT_EQ(Scene::joint_compliance_length(scene), 0.);
}

// The rigid law always; springs only while E/kn (1.79 m at kn = 9e9 Pa/m,
// 16.1 mm at 1e12, 0.16 mm at 1e14) is below the 10 mm fillet.
TEST(ContactIsExact, RigidLawOrSpringsStifferThanTheFillet)
{
  auto scene = default_scene();
  EXPECT_FALSE(Scene::contact_is_exact(scene));
  scene.joints.normal_stiffness = 1e12;
  EXPECT_FALSE(Scene::contact_is_exact(scene));
  scene.joints.normal_stiffness = 1e14;
  EXPECT_TRUE(Scene::contact_is_exact(scene));
  scene.joints.normal_stiffness         = 9e9;
  scene.geometry.corner_rounding_radius = 0.;
  EXPECT_FALSE(Scene::contact_is_exact(scene));
  scene.joints.law = Contact::JointLawKind::rigid;
  EXPECT_TRUE(Scene::contact_is_exact(scene));
  scene.geometry.corner_rounding_radius = 0.01;
  EXPECT_TRUE(Scene::contact_is_exact(scene));
}

TEST(GlobalRefinements, AutoKeepsTheGmshMeshForCompliantJoints)
{
  EXPECT_EQ(Scene::global_refinements(default_scene()), 0u);
}

// Default scene: Corner size 0.02 m, rounding radius 0.01 m.
TEST(GlobalRefinements, AutoHalvesUntilTheCornerCellsFitTheFillet)
{
  auto scene       = default_scene();
  scene.joints.law = Contact::JointLawKind::rigid;
  EXPECT_EQ(Scene::global_refinements(scene), 1u);
  scene.geometry.corner_rounding_radius = 0.005;
  EXPECT_EQ(Scene::global_refinements(scene), 2u);
  scene.geometry.corner_rounding_radius = 0.02;
  EXPECT_EQ(Scene::global_refinements(scene), 0u);
  // Capped: a fillet far below the corner size asks for a smaller Corner
  // size, not for refining every cell of the scene.
  scene.geometry.corner_rounding_radius = 1e-5;
  EXPECT_EQ(Scene::global_refinements(scene),
            Scene::max_auto_global_refinements);
}

TEST(GlobalRefinements, AutoLeavesSharpCornersAlone)
{
  auto scene                            = default_scene();
  scene.joints.law                      = Contact::JointLawKind::rigid;
  scene.geometry.corner_rounding_radius = 0.;
  EXPECT_EQ(Scene::global_refinements(scene), 0u);
}

// Joints stiff enough that E/kn < r behave like the rigid law at the corner.
TEST(GlobalRefinements, AutoTreatsVeryStiffJointsLikeTheRigidLaw)
{
  auto scene                    = default_scene();
  scene.joints.normal_stiffness = 1e14; // E/kn = 0.16 mm < 10 mm
  EXPECT_EQ(Scene::global_refinements(scene), 1u);
}

TEST(GlobalRefinements, AnExplicitCountWins)
{
  auto scene = default_scene({"Joints/Law=rigid", "Mesh/Global refinements=0"});
  EXPECT_EQ(Scene::global_refinements(scene), 0u);
  scene = default_scene({"Mesh/Global refinements=2"});
  EXPECT_EQ(Scene::global_refinements(scene), 2u);
}
