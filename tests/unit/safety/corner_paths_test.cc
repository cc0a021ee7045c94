// The paths the floor safety factor reads the stress along: both top
// corners of every vertical joint, along the inward bisector from the
// corner's surface point.

#include <safety/corner_paths.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "default_scene.h"

using namespace FloorBlock;

// Default scene: n = 6, L = 1 m, H = 2 m, r = 0.01 m. Joint j at
// x = (6 - j) m; block j on its +x side; the fillet's middle lies
// (sqrt(2) - 1) r along the bisector from the sharp corner (x_j, H).
TEST(CornerPaths, BothTopCornersOfEveryVerticalJoint)
{
  const auto   scene = Testing::default_scene();
  const auto   paths = Safety::floor_corner_paths(scene);
  const double r     = 0.01;
  const double inset = (std::sqrt(2.) - 1.) * r / std::sqrt(2.);
  ASSERT_EQ(paths.size(), 12u);
  std::set<std::string> blocks;
  for (const auto &path : paths)
    {
      const double x_joint = 6. - path.joint;
      const double side    = path.direction.x > 0. ? 1. : -1.;
      EXPECT_NEAR(std::hypot(path.direction.x, path.direction.y), 1., 1e-15);
      EXPECT_NEAR(path.direction.x, side / std::sqrt(2.), 1e-15);
      EXPECT_NEAR(path.direction.y, -1. / std::sqrt(2.), 1e-15);
      EXPECT_NEAR(path.start.x, x_joint + side * inset, 1e-12);
      EXPECT_NEAR(path.start.y, 2. - inset, 1e-12);
      EXPECT_EQ(path.joint_name, "vertical " + std::to_string(path.joint));
      // +x: block j itself; -x: block j + 1, or the face block at j = n.
      const std::string expected =
        side > 0. ? "block " + std::to_string(path.joint) :
        path.joint == 6 ? "face block" :
                          "block " + std::to_string(path.joint + 1);
      EXPECT_EQ(path.block, expected);
      blocks.insert(path.block + "@" + path.joint_name);
    }
  EXPECT_EQ(blocks.size(), 12u);
}

// Sharp corners: the path starts at the corner itself.
TEST(CornerPaths, SharpCornersStartAtTheCorner)
{
  const auto scene =
    Testing::default_scene({"Geometry/Corner rounding radius=0"});
  for (const auto &path : Safety::floor_corner_paths(scene))
    {
      EXPECT_NEAR(path.start.x, 6. - path.joint, 1e-12);
      EXPECT_NEAR(path.start.y, 2., 1e-12);
    }
}
