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
    const auto       &scene = Testing::meshed_scene("default");
    std::ifstream     file(scene.msh_path);
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

namespace FloorBlock::Geometry
{
  // A sweep meshes many scenes in one process: a scene's mesh must not
  // depend on what was meshed before it (Gmsh keeps global state between
  // scopes), or a sweep's results depend on the order of its cases.
  TEST(Mesher, SameSceneMeshesIdenticallyAfterOtherScenes)
  {
    // The mesh without the $Periodic section: Gmsh lists the periodic node
    // pairs in a different order from one GmshScope to the next (measured),
    // and deal.II does not read them; nodes and elements must be identical.
    const auto read = [](const std::string &path) {
      std::ifstream file(path);
      std::string   line, text;
      bool          periodic = false;
      while (std::getline(file, line))
        {
          periodic = periodic || line == "$Periodic";
          if (!periodic)
            text += line + '\n';
          periodic = periodic && line != "$EndPeriodic";
        }
      return text;
    };
    AssemblyDescription scene; // the default assembly
    scene.corner_rounding_radius = 0.01;
    const std::string first  = Testing::scratch_folder() + "/repeat_first.msh";
    const std::string second = Testing::scratch_folder() + "/repeat_second.msh";
    write_gmsh_mesh(scene, first);
    AssemblyDescription other = scene;
    other.n_blocks            = 3;
    other.mesh_corner_size    = 0.1;
    write_gmsh_mesh(other, Testing::scratch_folder() + "/repeat_other.msh");
    write_gmsh_mesh(scene, second);
    const std::string first_text = read(first), second_text = read(second);
    EXPECT_EQ(first_text.size(), second_text.size());
    EXPECT_TRUE(first_text == second_text)
      << "the mesh of a scene changed after meshing another scene";
  }
} // namespace FloorBlock::Geometry
