#include <corner/corner_profile.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace FloorBlock;
  using Contact::JointState;

  /**
   * A vertical joint along x = 0 from y = 0 to the fillet start at y = 1,
   * then nodes into the fillet (x < 0), spacing h; the traction is
   * K sqrt(edge - s) below the edge, open above.
   */
  Contact::JointReport
  joint_with_edge(const double edge_above_corner,
                  const double h,
                  const double k)
  {
    Contact::JointReport joint;
    joint.name = "vertical 1";
    for (int i = 0; i <= 200; ++i)
      {
        const double s = 0.5 + i * h; // arc position = y on the straight part
        Contact::JointNodeSample node;
        node.arc_position = s;
        node.position = dealii::Point<2>(s > 1. ? -(s - 1.) * (s - 1.) : 0., s);
        const double d       = 1. + edge_above_corner - s;
        node.state           = d > 0. ? JointState::stick : JointState::open;
        node.normal_traction = d > 0. ? k * std::sqrt(d) : 0.;
        node.tangential_traction = 0.1 * node.normal_traction;
        node.exact_traction      = true;
        joint.profile.push_back(node);
      }
    return joint;
  }

  Corner::CornerSite
  site_at_one()
  {
    Corner::CornerSite site;
    site.joint_name      = "vertical 1";
    site.rounding_radius = 0.01;
    site.corner          = {0., 1.};
    site.top             = 1.01;
    return site;
  }
} // namespace

TEST(CornerProfile, LocatesASquareRootEdgeInsideTheFilletBetweenNodes)
{
  // Edge 0.0333 above the corner, nodes every 0.01: between nodes.
  const double h = 0.01, edge = 0.0333, k = 2e8;
  const auto   profile =
    Corner::corner_profile(joint_with_edge(edge, h, k), site_at_one());
  EXPECT_EQ(profile.kind, Corner::CornerContactKind::edge_in_fillet);
  EXPECT_NEAR(profile.corner_arc, 1., 1e-12);
  // t^2 is linear in s, so its extrapolation finds the edge exactly.
  EXPECT_NEAR(profile.edge_beyond_corner, edge, 1e-9);
  EXPECT_NEAR(profile.edge_spacing, h, 1e-12);
  EXPECT_EQ(profile.edge_state, JointState::stick);
  EXPECT_NEAR(profile.edge_traction_ratio, 0.1, 1e-12);
  ASSERT_FALSE(profile.samples.empty());
  for (const auto &sample : profile.samples)
    EXPECT_NEAR(sample.traction,
                k * std::sqrt(sample.distance),
                1e-9 * sample.traction);
  // Nearest first; the peak is the farthest node of this monotone profile.
  EXPECT_LT(profile.samples.front().distance, profile.samples.back().distance);
  EXPECT_NEAR(profile.peak_distance, profile.samples.back().distance, 1e-12);
}

TEST(CornerProfile, ReadsAJointInEitherArcDirection)
{
  Contact::JointReport joint = joint_with_edge(0.0333, 0.01, 2e8);
  for (auto &node : joint.profile)
    node.arc_position = 10. - node.arc_position; // arc now runs downwards
  const auto profile = Corner::corner_profile(joint, site_at_one());
  EXPECT_EQ(profile.kind, Corner::CornerContactKind::edge_in_fillet);
  EXPECT_NEAR(profile.edge_beyond_corner, 0.0333, 1e-9);
}

TEST(CornerProfile, ContactUpToTheLastNodeReachesTheCorner)
{
  Contact::JointReport joint   = joint_with_edge(10., 0.01, 2e8);
  const auto           profile = Corner::corner_profile(joint, site_at_one());
  EXPECT_EQ(profile.kind, Corner::CornerContactKind::reaches_corner);
  // Distances from the last node; the last node itself is not a sample.
  EXPECT_NEAR(profile.samples.front().distance, 0.01, 1e-12);
}

TEST(CornerProfile, AZoneEndingBelowTheCornerIsOpenAtTheCorner)
{
  const auto profile =
    Corner::corner_profile(joint_with_edge(-0.2, 0.01, 2e8), site_at_one());
  EXPECT_EQ(profile.kind, Corner::CornerContactKind::open_at_corner);
  EXPECT_NEAR(profile.edge_beyond_corner, -0.2, 1e-9);
}

TEST(CornerProfile, RefusesAJointOpenEverywhere)
{
  Contact::JointReport joint = joint_with_edge(-10., 0.01, 2e8);
  EXPECT_THROW(Corner::corner_profile(joint, site_at_one()),
               std::runtime_error);
}
