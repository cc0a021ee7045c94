#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "process.h"

using namespace FloorBlockTest;

namespace
{
  /** The number before @p word in @p text ("2785 quadrilaterals"). */
  unsigned long
  count_before(const std::string &text, const std::string &word)
  {
    std::smatch match;
    if (!std::regex_search(text, match, std::regex("([0-9]+) " + word)))
      return 0;
    return std::stoul(match[1]);
  }
} // namespace

// Issue 16, first step: a 3D scene is the 2D assembly mesh swept along the
// face. The tool shall write <scene>_3d.msh with one hexahedron per
// quadrilateral and slice (1 m in 0.25 m slices: 4 per quadrilateral), the
// 2D mesh and its picture as before.
TEST(MeshCommand, ThreeDimensionalSceneIsTheSectionSweptAlongTheFace)
{
  const std::string folder = fresh_output_folder("mesh_3d");
  const auto        result = run_floorblock(
    "mesh params/default.prm --output " + shell_quoted(folder) +
    " --set 'Geometry/Dimension=3' --set 'Geometry/Face length=1'"
           " --set 'Mesh/Slice size=0.25'");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const unsigned long n_quadrilaterals =
    count_before(result.output, "quadrilaterals");
  ASSERT_GT(n_quadrilaterals, 0u) << result.output;
  EXPECT_EQ(count_before(result.output, "hexahedra"), 4 * n_quadrilaterals)
    << result.output;
  EXPECT_TRUE(std::filesystem::exists(folder + "/default.msh"));
  const std::string msh = read_text(folder + "/default_3d.msh");
  EXPECT_NE(msh.find("$NOD"), std::string::npos);
  EXPECT_NE(msh.find("$ELM"), std::string::npos);
}

// A plane scene writes no 3D mesh.
TEST(MeshCommand, PlaneSceneWritesNoThreeDimensionalMesh)
{
  const std::string folder = fresh_output_folder("mesh_2d");
  const auto        result =
    run_floorblock("mesh params/default.prm --output " + shell_quoted(folder));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output.find("hexahedra"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(folder + "/default_3d.msh"));
}
