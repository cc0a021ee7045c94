// Top fillets across vertical joints: recognised as mirror images on a level
// floor and meshed with mirror-image nodes (what the contact pairing needs).
#include <geometry/body_outline.h>
#include <geometry/ids.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "test_meshes.h"

namespace FloorBlock::Geometry
{
  namespace
  {
    /** Coordinates of mirrored nodes agree to this (m): round-off of the arc
     * evaluation. */
    constexpr double mirror_tolerance = 1e-12;
    /** The mesher's minimum: 4 cell edges on every fillet, so 5 nodes. */
    constexpr unsigned int min_fillet_nodes = 5;

    /** Vertices on the arc @p fillet (its boundary id, on its circle), sorted by height. */
    std::vector<dealii::Point<2>>
    vertices_on_arc(const dealii::Triangulation<2> &triangulation,
                    const Segment                  &fillet)
    {
      const dealii::Point<2> centre(fillet.control.x, fillet.control.y);
      const double radius = std::hypot(fillet.start.x - fillet.control.x,
                                       fillet.start.y - fillet.control.y);
      std::map<unsigned int, dealii::Point<2>> vertices;
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == fillet.boundary_id)
          for (const unsigned int vertex : face->vertex_indices())
            if (std::abs(face->vertex(vertex).distance(centre) - radius) <=
                mirror_tolerance)
              vertices[face->vertex_index(vertex)] = face->vertex(vertex);
      std::vector<dealii::Point<2>> points;
      for (const auto &entry : vertices)
        points.push_back(entry.second);
      std::sort(points.begin(), points.end(), [](const auto &a, const auto &b) {
        return a[1] < b[1];
      });
      return points;
    }
  } // namespace

  TEST(FilletPairs, LevelFloorFilletsAreMirrorImagesSlopedOnesAreNot)
  {
    EXPECT_TRUE(build_outline(Testing::scene_description("default"))
                  .fillet_pairs.empty());
    for (const std::string name : {"planar_rounded", "rounded"})
      {
        const AssemblyDescription description =
          Testing::scene_description(name);
        const AssemblyOutline outline = build_outline(description);
        // One pair per vertical joint, the face joint included.
        ASSERT_EQ(outline.fillet_pairs.size(), description.n_blocks) << name;
        for (unsigned int joint = 1; joint <= description.n_blocks; ++joint)
          {
            const FilletPair &pair = outline.fillet_pairs[joint - 1];
            const Segment    &master =
              outline.bodies[pair.master.body].segments[pair.master.segment];
            const Segment &slave =
              outline.bodies[pair.slave.body].segments[pair.slave.segment];
            EXPECT_EQ(master.kind, SegmentKind::arc);
            EXPECT_EQ(master.boundary_id, Ids::vertical_joint_free_side(joint));
            EXPECT_EQ(slave.boundary_id, Ids::vertical_joint_face_side(joint));
            EXPECT_DOUBLE_EQ(pair.joint_x,
                             (description.n_blocks - joint) *
                               description.block_width);
            // y = x^2/100 is sloped at every joint; at the face joint (x = 0)
            // its tangent is level but block n's fillet touches the rising
            // parabola while the face block's touches a line, so even there
            // the two differ (by far more than round-off).
            const bool level = name == "planar_rounded";
            EXPECT_EQ(pair.mirror, level) << name << " joint " << joint;
          }
      }
  }

  TEST(FilletPairs, MirrorFilletsAreMeshedWithMirrorImageNodes)
  {
    for (const std::string name : {"planar_rounded", "rounded"})
      {
        const auto           &scene   = Testing::meshed_scene(name);
        const AssemblyOutline outline = build_outline(scene.description);
        for (const FilletPair &pair : outline.fillet_pairs)
          {
            const auto master = vertices_on_arc(
              scene.triangulation,
              outline.bodies[pair.master.body].segments[pair.master.segment]);
            const auto slave = vertices_on_arc(
              scene.triangulation,
              outline.bodies[pair.slave.body].segments[pair.slave.segment]);
            EXPECT_GE(master.size(), min_fillet_nodes) << name;
            // Same count on both sides always (the slave takes the master's).
            ASSERT_EQ(master.size(), slave.size()) << name;
            if (!pair.mirror)
              continue;
            for (unsigned int k = 0; k < master.size(); ++k)
              {
                EXPECT_NEAR(slave[k][0],
                            2. * pair.joint_x - master[k][0],
                            mirror_tolerance)
                  << name << " node " << master[k];
                EXPECT_NEAR(slave[k][1], master[k][1], mirror_tolerance)
                  << name << " node " << master[k];
              }
          }
      }
  }
} // namespace FloorBlock::Geometry
