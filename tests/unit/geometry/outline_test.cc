#include <geometry/assembly_mesher.h>
#include <geometry/bedding_profile.h>
#include <geometry/body_outline.h>
#include <geometry/ids.h>

#include <gtest/gtest.h>

#include <cmath>

#include "test_meshes.h"

namespace FloorBlock::Geometry
{
  namespace
  {
    constexpr double area_tolerance = 1e-10; // relative, as the issue asks

    double
    relative_difference(const double value, const double reference)
    {
      return std::abs(value - reference) / std::abs(reference);
    }
  } // namespace

  TEST(BeddingProfile, ParabolaMatchesChapterCurve)
  {
    AssemblyDescription description;
    description.curvature      = 200.0;
    const BeddingProfile curve = BeddingProfile::geometry_profile(description);
    EXPECT_DOUBLE_EQ(curve.height(4.0), 16.0 / 200.0);
    EXPECT_DOUBLE_EQ(curve.slope(4.0), 8.0 / 200.0);
    EXPECT_DOUBLE_EQ(curve.height(-1.0), 0.0); // tangent continuation
    EXPECT_DOUBLE_EQ(curve.integral(0.0, 3.0), 27.0 / 600.0);
    // Bezier control point: the tangents at both ends meet there.
    const double control = curve.bezier_control_height(2.0, 4.0, 0.0);
    EXPECT_DOUBLE_EQ(control, curve.height(4.0) - curve.slope(4.0) * 1.0);
  }

  TEST(BeddingProfile, LiftedReadingMeshesFlat)
  {
    AssemblyDescription description;
    description.floor_uplift = FloorUplift::lifted_flat_bedding;
    EXPECT_EQ(BeddingProfile::geometry_profile(description).height(5.0), 0.0);
    EXPECT_DOUBLE_EQ(BeddingProfile::uplift_profile(description).height(5.0),
                     25.0 / 400.0);
  }

  TEST(Outline, OutlinesAreClosedAndCounterClockwise)
  {
    for (const std::string name :
         {"default", "planar", "rounded", "planar_rounded", "lifted"})
      {
        const AssemblyOutline outline =
          build_outline(Testing::scene_description(name));
        for (const BodyOutline &body : outline.bodies)
          {
            for (unsigned int index = 0; index < body.segments.size(); ++index)
              {
                const Segment &segment = body.segments[index];
                const Segment &next =
                  body.segments[(index + 1) % body.segments.size()];
                EXPECT_EQ(segment.end.x, next.start.x) << name;
                EXPECT_EQ(segment.end.y, next.start.y) << name;
              }
            EXPECT_GT(outline_area(body), 0.0) << name;
          }
      }
  }

  TEST(Outline, SharpBodyAreasAreClosedForm)
  {
    for (const std::string name : {"default", "planar", "lifted"})
      {
        const AssemblyDescription d       = Testing::scene_description(name);
        const AssemblyOutline     outline = build_outline(d);
        // Vertical sides and a top that is the bedding shifted up by H:
        // area = integral of H dx = L H for any profile.
        for (unsigned int block = 0; block < d.n_blocks; ++block)
          EXPECT_LT(relative_difference(outline_area(outline.bodies[block]),
                                        d.block_width * d.block_height),
                    area_tolerance)
            << name << " block " << block + 1;
        EXPECT_LT(relative_difference(outline_area(outline.bodies[d.n_blocks]),
                                      d.face_block_width * d.block_height),
                  area_tolerance);
        EXPECT_LT(relative_difference(outline_area(outline.bodies.back()),
                                      (d.n_blocks * d.block_width +
                                       d.face_block_width) *
                                        d.base_thickness),
                  area_tolerance);
      }
  }

  TEST(Outline, FilletsRemoveTheCornerArea)
  {
    // On a flat bedding every corner is 90 deg and a fillet of radius r
    // removes r^2 (1 - pi/4).
    const AssemblyDescription d = Testing::scene_description("planar_rounded");
    const double              r = d.corner_rounding_radius;
    const AssemblyOutline     outline     = build_outline(d);
    const double              corner_loss = r * r * (1.0 - M_PI / 4.0);
    EXPECT_LT(relative_difference(outline_area(outline.bodies[0]),
                                  d.block_width * d.block_height -
                                    4.0 * corner_loss),
              area_tolerance);
  }

  TEST(Outline, EveryJointPairsItsTwoSides)
  {
    for (const std::string name : {"default", "rounded", "planar"})
      {
        const AssemblyDescription d       = Testing::scene_description(name);
        const AssemblyOutline     outline = build_outline(d);
        // n vertical joints and n + 1 bedding joints (blocks + face block).
        EXPECT_EQ(outline.joint_pairs.size(), 2 * d.n_blocks + 1) << name;
        for (const JointPair &pair : outline.joint_pairs)
          {
            const auto master_id = outline.bodies[pair.master.body]
                                     .segments[pair.master.segment]
                                     .boundary_id;
            const auto slave_id = outline.bodies[pair.slave.body]
                                    .segments[pair.slave.segment]
                                    .boundary_id;
            const auto master_kind = Ids::boundary_kind(master_id);
            EXPECT_TRUE(master_kind ==
                          Ids::BoundaryKind::vertical_joint_free_side ||
                        master_kind == Ids::BoundaryKind::bedding_block_side);
            if (master_kind == Ids::BoundaryKind::vertical_joint_free_side)
              EXPECT_EQ(slave_id,
                        Ids::vertical_joint_face_side(
                          Ids::boundary_index(master_id)));
            else
              EXPECT_EQ(slave_id,
                        Ids::bedding_base_side(Ids::boundary_index(master_id)));
          }
      }
  }

  TEST(Outline, CadAreasAgreeWithExactAreas)
  {
    // OpenCASCADE integrates the CAD surfaces (Bezier pieces, arcs) on its
    // own; the outline areas come from Green's theorem in closed form.
    for (const std::string name : {"default", "rounded", "planar_rounded"})
      {
        const AssemblyDescription d       = Testing::scene_description(name);
        const AssemblyOutline     outline = build_outline(d);
        const std::vector<double> cad     = cad_body_areas(d);
        ASSERT_EQ(cad.size(), outline.bodies.size());
        double total = 0.0;
        for (unsigned int body = 0; body < cad.size(); ++body)
          {
            EXPECT_LT(relative_difference(cad[body],
                                          outline_area(outline.bodies[body])),
                      area_tolerance)
              << name << " body " << body;
            total += cad[body];
          }
        if (d.corner_rounding_radius == 0.0)
          {
            EXPECT_LT(relative_difference(
                        total,
                        (d.n_blocks * d.block_width + d.face_block_width) *
                          (d.block_height + d.base_thickness)),
                      area_tolerance);
          }
      }
  }
} // namespace FloorBlock::Geometry
