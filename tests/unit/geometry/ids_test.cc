#include <geometry/ids.h>

#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>

namespace FloorBlock::Geometry::Ids
{
  // The expected numbers are the agreed scheme as written in the project
  // brief, not values produced by the code.
  TEST(Ids, AgreedSchemeValues)
  {
    EXPECT_EQ(block_material(1), 1u);
    EXPECT_EQ(block_material(99), 99u);
    EXPECT_EQ(face_block_material, 100u);
    EXPECT_EQ(base_material, 101u);
    EXPECT_EQ(vertical_joint_free_side(3), 2003u);
    EXPECT_EQ(vertical_joint_face_side(6), 3006u);
    EXPECT_EQ(bedding_block_side(2), 4002u);
    EXPECT_EQ(bedding_base_side(0), 5000u);
    EXPECT_EQ(floor_surface(0), 6000u);
    EXPECT_EQ(floor_surface(4), 6004u);
    EXPECT_EQ(base_bottom, 7001u);
    EXPECT_EQ(base_end_face_side, 7002u);
    EXPECT_EQ(base_end_free_side, 7003u);
    EXPECT_EQ(free_side_of_block_1, 7004u);
    EXPECT_EQ(face_block_outer_side, 7005u);
    EXPECT_EQ(footprint_surface(1), 8001u);
    EXPECT_EQ(footprint_surface(6), 8006u);
  }

  TEST(Ids, KindAndIndexDecodeEveryId)
  {
    for (unsigned int index = 1; index <= max_n_blocks; ++index)
      {
        EXPECT_EQ(boundary_kind(vertical_joint_free_side(index)),
                  BoundaryKind::vertical_joint_free_side);
        EXPECT_EQ(boundary_kind(vertical_joint_face_side(index)),
                  BoundaryKind::vertical_joint_face_side);
        EXPECT_EQ(boundary_index(vertical_joint_face_side(index)), index);
        EXPECT_EQ(boundary_kind(bedding_block_side(index)),
                  BoundaryKind::bedding_block_side);
        EXPECT_EQ(boundary_index(bedding_base_side(index)), index);
        EXPECT_EQ(boundary_kind(floor_surface(index)),
                  BoundaryKind::floor_surface);
      }
    EXPECT_EQ(boundary_kind(free_side_of_block_1), BoundaryKind::outer);
    EXPECT_EQ(boundary_kind(0), BoundaryKind::unknown);
    EXPECT_EQ(boundary_kind(2000), BoundaryKind::unknown);
    EXPECT_EQ(boundary_kind(end_face_near), BoundaryKind::outer);
    EXPECT_EQ(boundary_kind(end_face_far), BoundaryKind::outer);
    EXPECT_EQ(boundary_kind(7008), BoundaryKind::unknown);
    EXPECT_EQ(boundary_kind(8000), BoundaryKind::unknown);
    EXPECT_EQ(boundary_kind(footprint_surface(1)),
              BoundaryKind::footprint_surface);
    EXPECT_EQ(boundary_index(footprint_surface(max_n_blocks)), max_n_blocks);
    EXPECT_FALSE(is_joint_side(footprint_surface(1)));
    EXPECT_TRUE(is_joint_side(bedding_base_side(0)));
    EXPECT_FALSE(is_joint_side(floor_surface(1)));
    EXPECT_FALSE(is_joint_side(base_bottom));
  }

  TEST(Ids, TableListsEveryIdOnceForLargestAssembly)
  {
    const std::string      table = id_table(max_n_blocks);
    std::istringstream     lines(table);
    std::string            line;
    std::set<unsigned int> seen;
    unsigned int           n_rows = 0;
    while (std::getline(lines, line))
      {
        std::istringstream fields(line);
        unsigned int       id = 0;
        if (fields >> id)
          {
            ++n_rows;
            seen.insert(id);
          }
      }
    // Materials: n blocks + face + base. Boundaries: 2n vertical joint
    // sides, 2(n+1) bedding sides, n+1 floor surfaces, 5 outer, the 2
    // end faces and the n footprint tops of 3D scenes.
    const unsigned int n = max_n_blocks;
    EXPECT_EQ(n_rows, (n + 2) + 2 * n + 2 * (n + 1) + (n + 1) + 5 + 2 + n);
    // Material and boundary ids live in different spaces, so only the
    // boundary ids have to be distinct from each other: 1..101 < 2000.
    EXPECT_EQ(seen.size(), n_rows);
  }

  TEST(Ids, TableNamesFaceBlockSideOfLastJoint)
  {
    const std::string table = id_table(6);
    EXPECT_NE(table.find("3006  vertical joint 6, face block side"),
              std::string::npos)
      << table;
    EXPECT_NE(table.find("3005  vertical joint 5, block 6 side"),
              std::string::npos);
    EXPECT_NE(table.find("5000  bedding joint under face block, base top"),
              std::string::npos);
  }
} // namespace FloorBlock::Geometry::Ids
