// The floor safety factor of a solve: evaluated at every floor-level block
// corner where the mesh resolves the critical distance, refused with the
// size it needs where it does not.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  const std::string three_blocks = "tests/scenarios/three_blocks.prm";

  // Cells of L/8 along the corner paths: every corner resolved, the
  // governing corner the smallest point-method factor, the paths written.
  TEST(FloorSafety, ResolvedCornersGiveBothFactors)
  {
    const std::string folder = fresh_output_folder("floor_safety_resolved");
    const auto        solve  = run_floorblock(
      "solve " + three_blocks +
      " --set \"Strength/Critical distance=0.05\""
      " --set \"Mesh/Cells per critical distance=8\" --output " +
      shell_quoted(folder));
    ASSERT_EQ(solve.exit_code, 0) << solve.output;
    EXPECT_NE(solve.output.find("floor safety (Hoek-Brown, critical "
                                "distance L = 50.0 mm)"),
              std::string::npos)
      << solve.output;

    const json safety = read_json(folder + "/fem.json")["floor_safety"];
    ASSERT_EQ(safety["corners"].size(), 6u); // 3 joints, 2 corners each
    double smallest = 1e300;
    for (const json &corner : safety["corners"])
      {
        EXPECT_TRUE(corner["resolved"].get<bool>()) << corner.dump();
        EXPECT_LE(corner["largest_cell_m"].get<double>(), 0.05 / 4. + 1e-12);
        const double point = corner["safety_factor_point"];
        const double line  = corner["safety_factor_line"];
        EXPECT_GT(point, 0.);
        EXPECT_GT(line, 0.);
        EXPECT_LE(point, 100.);
        smallest = std::min(smallest, point);
      }
    EXPECT_DOUBLE_EQ(safety["governing"]["safety_factor_point"].get<double>(),
                     smallest);
    EXPECT_EQ(safety["governing"]["status"],
              smallest < 1. ? "fails" : "holds");
    EXPECT_TRUE(std::filesystem::exists(folder + "/floor_safety_paths.csv"));
  }

  // The scene's own mesh (cells of 0.1 m at the corners) against the
  // default L of 9.7 mm: no factor, the size it would need, no paths file.
  TEST(FloorSafety, UnresolvedMeshNamesTheSizeItNeeds)
  {
    const std::string folder = fresh_output_folder("floor_safety_coarse");
    const auto        solve  = run_floorblock("solve " + three_blocks +
                                      " --output " + shell_quoted(folder));
    ASSERT_EQ(solve.exit_code, 0) << solve.output;
    EXPECT_NE(solve.output.find("floor safety: not evaluated"),
              std::string::npos)
      << solve.output;
    EXPECT_NE(solve.output.find("Mesh/Cells per critical distance"),
              std::string::npos);
    const json safety = read_json(folder + "/fem.json")["floor_safety"];
    EXPECT_EQ(safety["status"], "unresolved");
    EXPECT_FALSE(safety.contains("governing"));
    EXPECT_FALSE(std::filesystem::exists(folder + "/floor_safety_paths.csv"));
  }
} // namespace
