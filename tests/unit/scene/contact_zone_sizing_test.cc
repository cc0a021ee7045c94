// Scene::closed_form_contact_zones: cells sized from Eq. 6.51's contact
// length along the upper end of every vertical joint;
// Scene::computed_contact_zones: from the zones a solve computed.

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
  const auto   zones = Scene::closed_form_contact_zones(scene);
  EXPECT_EQ(zones.source, Scene::ContactZoneSource::closed_form);
  EXPECT_DOUBLE_EQ(zones.contact_length, c);
  const auto &sizes = zones.sizes;
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
  const auto zones = Scene::closed_form_contact_zones(scene);
  ASSERT_FALSE(zones.sizes.empty());
  for (const auto &local : zones.sizes)
    EXPECT_DOUBLE_EQ(local.size, scene.mesh.corner_size);
}

TEST(ContactZoneSizes, ZeroCellsTurnsTheSizingOff)
{
  const auto zones = Scene::closed_form_contact_zones(
    default_scene({"Mesh/Cells per contact length=0"}));
  EXPECT_EQ(zones.source, Scene::ContactZoneSource::not_asked);
  EXPECT_TRUE(zones.sizes.empty());
}

// A bed dipping 5 deg away from the face: the face joint closes at its foot
// (y < -y*) and no mechanism gives Eq. 6.51 a contact length, so the
// closed forms give no sizes and say why.
TEST(ContactZoneSizes, NoneWhereEqSixFiftyOneHasNoAnswer)
{
  const auto scene = default_scene(
    {"Bedding/Shape=planar", "Bedding/Inclination=-5"});
  EXPECT_FALSE(Scene::estimated_contact_length(scene).has_value());
  const auto zones = Scene::closed_form_contact_zones(scene);
  EXPECT_EQ(zones.source, Scene::ContactZoneSource::none);
  EXPECT_TRUE(zones.sizes.empty());
  EXPECT_NE(zones.reason.find("Eq. 6.51"), std::string::npos);
}

namespace
{
  /** A vertical joint at x from y = 0 to 2 m, nodes every 0.1 m, closed
   * from y = 0 to @p closed_to. */
  Contact::JointReport
  vertical_joint(const double x, const double closed_to)
  {
    Contact::JointReport joint;
    joint.name = "vertical 1";
    for (unsigned int k = 0; k <= 20; ++k)
      {
        Contact::JointNodeSample node;
        node.arc_position = 0.1 * k;
        node.position     = dealii::Point<2>(x, 0.1 * k);
        node.state        = node.arc_position <= closed_to + 1e-12 ?
                              Contact::JointState::stick :
                              Contact::JointState::open;
        joint.profile.push_back(node);
      }
    joint.closed_length = closed_to;
    return joint;
  }
} // namespace

// Each computed zone gets cells of its own c / N over the zone and c/2
// beyond its open end, clipped at the joint's end; open joints and other
// joints than the vertical ones get none; the reported length is the shortest.
TEST(ContactZoneSizes, FollowTheZonesASolveComputed)
{
  const auto scene = default_scene();
  const unsigned int n = scene.mesh.cells_per_contact_length;
  Contact::JointReport open = vertical_joint(3., -1.);
  open.closed_length        = 0.;
  Contact::JointReport bedding = vertical_joint(4., 0.4);
  bedding.name                 = "bedding 1";
  const auto zones = Scene::computed_contact_zones(
    scene, {vertical_joint(0., 0.4), vertical_joint(1., 0.8), open, bedding});
  EXPECT_EQ(zones.source, Scene::ContactZoneSource::first_solve);
  EXPECT_DOUBLE_EQ(zones.contact_length, 0.4);
  std::map<long, std::pair<double, double>> extent; // x -> lowest, highest y
  for (const auto &local : zones.sizes)
    {
      const long x = std::lround(local.position.x);
      ASSERT_TRUE(x == 0 || x == 1) << "only the closed vertical joints";
      EXPECT_DOUBLE_EQ(local.size, (x == 0 ? 0.4 : 0.8) / n);
      auto [where, fresh] =
        extent.try_emplace(x, local.position.y, local.position.y);
      where->second.first  = std::min(where->second.first, local.position.y);
      where->second.second = std::max(where->second.second, local.position.y);
    }
  ASSERT_EQ(extent.size(), 2u);
  EXPECT_DOUBLE_EQ(extent[0].first, 0.);
  EXPECT_NEAR(extent[0].second, 0.4 + 0.2, 1e-12);
  EXPECT_DOUBLE_EQ(extent[1].first, 0.);
  EXPECT_NEAR(extent[1].second, 0.8 + 0.4, 1e-12);
}

TEST(ContactZoneSizes, NoneWhereTheSolveClosedNoVerticalJoint)
{
  Contact::JointReport open = vertical_joint(0., -1.);
  open.closed_length        = 0.;
  const auto zones = Scene::computed_contact_zones(default_scene(), {open});
  EXPECT_EQ(zones.source, Scene::ContactZoneSource::none);
  EXPECT_TRUE(zones.sizes.empty());
  EXPECT_FALSE(zones.reason.empty());
}

// Critical-distance sizing: cells of L/N along both bisectors of every
// vertical joint's top corner, from the sharp corner out to 1.5 L + r.
TEST(CriticalDistanceSizes, FollowTheCornerBisectors)
{
  const auto scene = default_scene({"Mesh/Cells per critical distance=8",
                                    "Strength/Critical distance=0.02"});
  const auto sizes = Scene::critical_distance_sizes(scene);
  ASSERT_FALSE(sizes.empty());
  const double r = scene.geometry.corner_rounding_radius;
  std::map<long, unsigned int> per_joint;
  for (const auto &local : sizes)
    {
      EXPECT_DOUBLE_EQ(local.size, 0.02 / 8.);
      const long   joint_x = std::lround(local.position.x);
      const double dx      = local.position.x - joint_x;
      const double dy      = 2. - local.position.y; // top: H = 2 m
      EXPECT_NEAR(std::abs(dx), dy, 1e-9) << "on a bisector";
      EXPECT_LE(std::hypot(dx, dy), 1.5 * 0.02 + r + 1e-9);
      ++per_joint[joint_x];
    }
  EXPECT_EQ(per_joint.size(), 6u);
}

TEST(CriticalDistanceSizes, NoneWhenNotAskedForOrInThreeDimensions)
{
  auto scene = default_scene();
  ASSERT_EQ(scene.mesh.cells_per_critical_distance, 16u) << "params/default.prm";
  EXPECT_FALSE(Scene::critical_distance_sizes(scene).empty());
  scene.mesh.cells_per_critical_distance = 0;
  EXPECT_TRUE(Scene::critical_distance_sizes(scene).empty());
  // The corner factors come from 2D solves; a swept 3D mesh needs none.
  scene.mesh.cells_per_critical_distance = 16;
  scene.geometry.dimension               = 3;
  EXPECT_TRUE(Scene::critical_distance_sizes(scene).empty());
}
