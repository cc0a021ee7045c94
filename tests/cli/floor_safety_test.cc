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
    const auto        solve =
      run_floorblock("solve " + three_blocks +
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
        smallest = std::min(smallest, line);
      }
    // With compliant joints the verdict and the governing corner go by
    // the line method.
    EXPECT_EQ(safety["governing"]["verdict_method"], "line");
    EXPECT_DOUBLE_EQ(safety["governing"]["safety_factor_line"].get<double>(),
                     smallest);
    EXPECT_EQ(safety["governing"]["status"], smallest < 1. ? "fails" : "holds");
    EXPECT_TRUE(std::filesystem::exists(folder + "/floor_safety_paths.csv"));
  }

  // With exact contact the verdict and the governing corner go by the area
  // method (Safety::verdict_method()): every corner has the three factors,
  // the governing one the smallest area-method factor, and the terminal
  // names the method.
  TEST(FloorSafety, ExactContactGoesByTheAreaMethod)
  {
    const std::string folder = fresh_output_folder("floor_safety_exact");
    const auto        solve =
      run_floorblock("solve " + three_blocks +
                     " --set \"Strength/Critical distance=0.05\""
                     " --set \"Mesh/Cells per critical distance=8\""
                     " --set \"Joints/Law=rigid\" --output " +
                     shell_quoted(folder));
    ASSERT_EQ(solve.exit_code, 0) << solve.output;
    EXPECT_NE(solve.output.find("(area method, the verdict)"), std::string::npos)
      << solve.output;

    const json safety = read_json(folder + "/fem.json")["floor_safety"];
    ASSERT_EQ(safety["corners"].size(), 6u);
    double smallest = 1e300;
    for (const json &corner : safety["corners"])
      {
        EXPECT_TRUE(corner["resolved"].get<bool>()) << corner.dump();
        for (const char *key :
             {"safety_factor_point", "safety_factor_line", "safety_factor_area"})
          {
            const double factor = corner[key];
            EXPECT_TRUE(factor > 0. && factor <= 100.) << key;
          }
        smallest = std::min(smallest, corner["safety_factor_area"].get<double>());
      }
    EXPECT_EQ(safety["governing"]["verdict_method"], "area");
    EXPECT_DOUBLE_EQ(safety["governing"]["safety_factor_area"].get<double>(),
                     smallest);
    EXPECT_EQ(safety["governing"]["status"], smallest < 1. ? "fails" : "holds");
  }

  // A strong rock's short L: the default scene at sigma_ci = 60 MPa has
  // L = 4.3 mm, and Gmsh, grading towards the paths' requests of L/16 among
  // the contact zones' own, leaves cells of up to 1.6 mm there (more than
  // L/4). deal.II halves the cells the paths cross until each is within
  // sqrt(2) of L/16, both joint sides alike, so every corner is resolved
  // and the scene still solves.
  TEST(FloorSafety, ShortCriticalDistanceIsResolvedByRefiningThePaths)
  {
    const std::string folder = fresh_output_folder("floor_safety_short_L");
    const auto        solve  = run_floorblock(
      "solve tests/scenarios/default.prm --set \"Strength/Intact UCS=60e6\""
              " --output " +
      shell_quoted(folder));
    ASSERT_EQ(solve.exit_code, 0) << solve.output;
    const json fem = read_json(folder + "/fem.json");
    EXPECT_EQ(fem["status"], "converged") << fem["status_text"];
    const json   safety = fem["floor_safety"];
    const double L      = safety["critical_distance_m"];
    EXPECT_NEAR(L, 4.33e-3, 0.01e-3);
    ASSERT_EQ(safety["corners"].size(), 12u); // 6 joints, 2 corners each
    for (const json &corner : safety["corners"])
      {
        EXPECT_TRUE(corner["resolved"].get<bool>()) << corner.dump();
        EXPECT_LE(corner["largest_cell_m"].get<double>(), L / 4.)
          << corner.dump();
      }
    EXPECT_TRUE(safety.contains("governing"));
  }

  // The scene's own mesh (cells of 0.1 m at the corners) against the
  // default L of 9.7 mm: no factor, the size it would need, no paths file.
  TEST(FloorSafety, UnresolvedMeshNamesTheSizeItNeeds)
  {
    const std::string folder = fresh_output_folder("floor_safety_coarse");
    const auto solve = run_floorblock("solve " + three_blocks + " --output " +
                                      shell_quoted(folder));
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

  // run's answer: the governing corner's factors with their estimated
  // errors (the level's check resolves the paths too), the chapter's
  // route beside them, FS along the lift, and the strength-factor field in
  // the VTU files and around the face corner.
  TEST(FloorSafety, RunReportsTheFactorsWithErrorsAlongTheLift)
  {
    const std::string folder = fresh_output_folder("floor_safety_run");
    const auto        run    = run_floorblock(
      "run " + three_blocks +
      " --set \"Strength/Critical distance=0.05\""
                " --set \"Mesh/Cells per critical distance=8\" --set "
                "\"Solver/FE degree=1\" --set \"Solver/Error estimate=refined solve\" "
                "--output " +
      shell_quoted(folder));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("floor safety at the governing corner"),
              std::string::npos)
      << run.output;
    EXPECT_NE(run.output.find("floor safety along the lift"),
              std::string::npos);
    const json safety = read_json(folder + "/summary.json")["floor_safety"];
    ASSERT_TRUE(safety.contains("governing")) << safety.dump(1);
    const json &governing = safety["governing"];
    EXPECT_EQ(governing["status"], "estimated");
    EXPECT_GE(governing["safety_factor_point_relative_error"].get<double>(),
              0.);
    EXPECT_GE(governing["safety_factor_line_relative_error"].get<double>(), 0.);
    EXPECT_TRUE(safety.contains("floor_strength_Pa"));
    const json &along = safety["along_lift"];
    ASSERT_GT(along["lift_m"].size(), 0u);
    EXPECT_EQ(along["lift_m"].size(), along["safety_factor_point"].size());
    // The last increment of the lift is the reported state.
    EXPECT_NEAR(along["safety_factor_point"].back().get<double>(),
                governing["safety_factor_point"].get<double>(),
                1e-12);
    EXPECT_TRUE(std::filesystem::exists(folder + "/floor_safety_vs_lift.png"));
    EXPECT_TRUE(std::filesystem::exists(folder + "/strength_factor.png"));
    EXPECT_NE(read_text(folder + "/vtu/solution-0000.vtu")
                .find("Name=\"strength_factor\""),
              std::string::npos);
    const std::string report = read_text(folder + "/report.md");
    EXPECT_NE(report.find("## Floor safety"), std::string::npos);
  }
} // namespace
