#include <geometry/assembly_mesher.h>

#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "test_meshes.h"

namespace FloorBlock::Geometry
{
  TEST(Mesher, DefaultSceneIsSmallAndFast)
  {
    const auto &scene = Testing::meshed_scene("default");
    const auto &stats = scene.statistics;
    std::cout << "default scene: " << stats.n_cells << " quadrilaterals, "
              << stats.n_nodes << " nodes, " << stats.n_bodies << " bodies, "
              << stats.n_matched_pairs << " matched joint sides, "
              << stats.wall_time << " s\n";
    EXPECT_EQ(stats.n_bodies, scene.description.n_blocks + 2);
    EXPECT_EQ(stats.n_matched_pairs, 2 * scene.description.n_blocks + 1);
    EXPECT_GT(stats.n_cells, 0u);
    // Timing is reported above, not asserted (shared, noisy machines). A
    // size field that stops working shows up as a cell count explosion: the
    // default scene has about 1100 cells.
    constexpr std::size_t max_default_cells = 2000;
    EXPECT_LT(stats.n_cells, max_default_cells);
    EXPECT_EQ(scene.triangulation.n_active_cells(), stats.n_cells);
  }

  TEST(Mesher, FileCarriesNamedPhysicalGroups)
  {
    const auto   &scene = Testing::meshed_scene("default");
    std::ifstream file(scene.msh_path);
    std::stringstream text;
    text << file.rdbuf();
    const std::string contents = text.str();
    EXPECT_NE(contents.find("$MeshFormat\n4.1"), std::string::npos);
    EXPECT_NE(contents.find("\"vertical joint 6, face block side\""),
              std::string::npos);
    EXPECT_NE(contents.find("\"base (bedding layer)\""), std::string::npos);
  }

  TEST(Mesher, NonMatchingSceneStillMeshesWithQuads)
  {
    // write_gmsh_mesh throws if any cell is not a quadrilateral.
    const auto &scene = Testing::meshed_scene("non_matching");
    EXPECT_EQ(scene.statistics.n_matched_pairs, 0u);
    EXPECT_GT(scene.statistics.n_cells, 0u);
  }
} // namespace FloorBlock::Geometry
