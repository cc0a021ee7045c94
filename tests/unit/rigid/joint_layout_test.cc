// Integration points, sides and normals of the joints, block loads.

#include <rigid/block_loads.h>
#include <rigid/joint_layout.h>

#include <gtest/gtest.h>

#include <cmath>

#include "scene_fixture.h"

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    /** Exact arc length of y = x^2/k from x_a to x_b (m). */
    double
    parabola_arc_length(const double x_a, const double x_b, const double k)
    {
      // With s = 2x/k: integral of sqrt(1 + s^2) (k/2) ds.
      const auto primitive = [k](const double x) {
        const double s = 2. * x / k;
        return k / 4. * (s * std::sqrt(1. + s * s) + std::asinh(s));
      };
      return primitive(x_b) - primitive(x_a);
    }
  } // namespace

  TEST(RigidJointLayout, SidesFollowTheChapterNumbering)
  {
    Geometry::AssemblyDescription assembly;
    assembly.n_blocks                       = 4;
    const std::vector<JointGeometry> joints = build_joints(assembly, 11);
    ASSERT_EQ(joints.size(), 8u);
    for (unsigned int j = 1; j <= 4; ++j)
      {
        const JointGeometry &vertical = joints[j - 1];
        EXPECT_EQ(vertical.kind, JointKind::vertical);
        EXPECT_EQ(vertical.number, j);
        EXPECT_EQ(vertical.side_a.kind, BodyKind::block);
        EXPECT_EQ(vertical.side_a.index, j - 1);
        if (j < 4)
          {
            EXPECT_EQ(vertical.side_b.kind, BodyKind::block);
            EXPECT_EQ(vertical.side_b.index, j);
          }
        else
          EXPECT_EQ(vertical.side_b.kind, BodyKind::face_block);
        // Joint j lies at x = (n - j) L, between the top at floor level and
        // the bedding.
        const double x_joint = (4. - j) * assembly.block_width;
        EXPECT_DOUBLE_EQ(vertical.points.front().position[0], x_joint);
        EXPECT_DOUBLE_EQ(vertical.points.front().position[1],
                         x_joint * x_joint / assembly.curvature +
                           assembly.block_height);
        // y_top - H: one rounding of a 2 m height.
        EXPECT_NEAR(vertical.points.back().position[1],
                    x_joint * x_joint / assembly.curvature,
                    1e-15);

        const JointGeometry &bedding = joints[4 + j - 1];
        EXPECT_EQ(bedding.kind, JointKind::bedding);
        EXPECT_EQ(bedding.side_a.kind, BodyKind::base);
        EXPECT_EQ(bedding.side_b.index, j - 1);
      }
  }

  TEST(RigidJointLayout, WeightsIntegrateLengthsAndNormalsAreUnit)
  {
    Geometry::AssemblyDescription assembly;
    assembly.curvature = 50.; // steep parabola: arc factor matters
    constexpr unsigned int           n_points = 401;
    const std::vector<JointGeometry> joints = build_joints(assembly, n_points);
    for (const JointGeometry &joint : joints)
      {
        double total = 0.;
        for (const JointPoint &point : joint.points)
          {
            total += point.weight;
            EXPECT_NEAR(point.normal.norm(), 1., 1e-15);
            EXPECT_NEAR(point.normal * point.tangent, 0., 1e-15);
          }
        if (joint.kind == JointKind::vertical)
          EXPECT_NEAR(total, assembly.block_height, 1e-13);
        else
          {
            const double x_start =
              (assembly.n_blocks - joint.number) * assembly.block_width;
            const double exact =
              parabola_arc_length(x_start,
                                  x_start + assembly.block_width,
                                  assembly.curvature);
            // Trapezoid error of a smooth integrand: (b - a) h^2 f''/12 with
            // f'' <= 4/k^2 for sqrt(1 + (2x/k)^2); h = L/400.
            const double spacing = assembly.block_width / (n_points - 1);
            EXPECT_NEAR(total,
                        exact,
                        assembly.block_width * spacing * spacing * 4. /
                          (12. * assembly.curvature * assembly.curvature));
          }
      }
  }

  TEST(RigidJointLayout, SupportLoadActsAtItsStatedPosition)
  {
    ModelDescription description         = Testing::default_scene(1);
    description.support_load_position    = 0.25;
    const std::vector<BlockLoads> loads  = block_loads(description);
    const double                  length = description.assembly.block_width;
    for (unsigned int index = 0; index < loads.size(); ++index)
      {
        // A quarter of L from the side away from the face.
        const double x_away = (loads.size() - index) * length;
        EXPECT_DOUBLE_EQ(loads[index].support_point[0], x_away - 0.25 * length);
        EXPECT_DOUBLE_EQ(loads[index].centroid[0], x_away - 0.5 * length);
        const std::array<double, 3> applied =
          applied_force(loads[index], 1., 1.);
        EXPECT_DOUBLE_EQ(applied[1],
                         -loads[index].weight - loads[index].support_load);
        // The load sits 0.25 L farther from the face than the centroid:
        // clockwise moment.
        EXPECT_DOUBLE_EQ(applied[2],
                         -0.25 * length * loads[index].support_load);
      }
  }
} // namespace FloorBlock::RigidBlocks
