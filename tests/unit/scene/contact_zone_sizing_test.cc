// Scene::contact_zone_sizes: cells sized from Eq. 6.51's contact length
// along the upper end of every vertical joint.

#include <analytic/corner_contact.h>
#include <scene/closed_forms.h>
#include <scene/mesh_sizing.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "default_scene.h"

using namespace FloorBlock;

using Testing::default_scene;

// The estimate is the shortest contact length among the mechanisms with
// one: on the default scene no_rotation's A / b (0.689 m^2 over 1.5 m;
// the other two have no answer or a longer one).
TEST(EstimatedContactLength, IsTheShortestMechanismContactLength)
{
  const auto scene    = default_scene();
  const auto closed   = Scene::evaluate_closed_forms(scene);
  double     shortest = INFINITY;
  for (const auto &mechanism : closed.mechanisms)
    if (mechanism.contact.status == Analytic::Status::ok &&
        mechanism.contact.contact_length > 0.)
      shortest = std::min(shortest, mechanism.contact.contact_length);
  ASSERT_TRUE(std::isfinite(shortest));
  const auto estimate = Scene::estimated_contact_length(scene);
  ASSERT_TRUE(estimate.has_value());
  EXPECT_DOUBLE_EQ(*estimate, shortest);
  EXPECT_NEAR(*estimate, 0.689 / 1.5, 0.002);
}

// Default scene: 6 vertical joints at x = 0..5 m (block i in
// [(n - i) L, (n - i + 1) L]); on each, sizes c / 8 from the joint side's
// upper end (the top fillet's start) down to 1.5 c, none below.
TEST(ContactZoneSizes, CoverTheUpperEndOfEveryVerticalJoint)
{
  const auto   scene = default_scene();
  const double c     = *Scene::estimated_contact_length(scene);
  const double size  = c / scene.mesh.cells_per_contact_length;
  const auto   sizes = Scene::contact_zone_sizes(scene);
  ASSERT_FALSE(sizes.empty());
  std::map<long, std::pair<double, double>> extent; // x -> lowest, highest y
  for (const auto &local : sizes)
    {
      EXPECT_DOUBLE_EQ(local.size, size);
      const double x = local.position.x;
      EXPECT_NEAR(x, std::round(x), 1e-9) << "on a joint line";
      auto [where, fresh] =
        extent.try_emplace(std::lround(x), local.position.y, local.position.y);
      where->second.first  = std::min(where->second.first, local.position.y);
      where->second.second = std::max(where->second.second, local.position.y);
    }
  ASSERT_EQ(extent.size(), 6u);
  for (const auto &[x, range] : extent)
    {
      EXPECT_GT(range.second, 1.9) << "x = " << x << ": the upper end";
      EXPECT_NEAR(range.second - range.first, 1.5 * c, 1e-9) << "x = " << x;
    }
}

TEST(ContactZoneSizes, NeverFinerThanTheCornerSize)
{
  const auto scene = default_scene({"Mesh/Cells per contact length=100"});
  for (const auto &local : Scene::contact_zone_sizes(scene))
    EXPECT_DOUBLE_EQ(local.size, scene.mesh.corner_size);
}

TEST(ContactZoneSizes, ZeroCellsTurnsTheSizingOff)
{
  EXPECT_TRUE(Scene::contact_zone_sizes(
                default_scene({"Mesh/Cells per contact length=0"}))
                .empty());
}
