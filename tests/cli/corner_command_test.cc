// `floorblock corner` end to end (issue 15): a coarse zoom on the 3-block
// scene with 5 cm fillets, its outputs, and the inputs it refuses.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  const std::string rounded_scene = "tests/scenarios/hard_rounded_corners.prm";

  ProcessResult
  corner(const std::string &output, const std::string &settings)
  {
    return run_floorblock("corner " + rounded_scene + " --output " +
                          shell_quoted(output) + " " + settings);
  }
} // namespace

// The tool shall report the corner's state, theory, fit, levels and the
// rounding study (radius_m, sigma_max_Pa) in corner.json, with the tables
// and plots beside it, and reuse the scene's own radius' zoom in the study.
TEST(CornerCommand, ReportsStateTheoryFitLevelsAndTheRoundingStudy)
{
  const std::string   output = fresh_output_folder("corner_coarse");
  const ProcessResult process =
    corner(output,
           "--set Joints/Law=rigid --set \"Corner/Zoom levels=3\" "
           "--set \"Corner/Rounding radii=0.05, 0.02\"");
  ASSERT_EQ(process.exit_code, 0) << process.output;
  for (const char *name : {"corner.json",
                           "corner_traction.csv",
                           "corner_levels.csv",
                           "corner_mean_pressure.csv",
                           "rounding_study.csv",
                           "corner_traction.png",
                           "rounding_study.png",
                           "summary.json",
                           "zoom/level_3/fem.json",
                           "rounding/radius_0.02_m/level_0/fem.json"})
    EXPECT_TRUE(std::filesystem::exists(output + "/" + name)) << name;
  for (const char *name : {"corner.json",
                           "corner_traction.csv",
                           "corner_levels.csv",
                           "corner_mean_pressure.csv",
                           "rounding_study.csv"})
    EXPECT_FALSE(has_non_finite_value(read_text(output + "/" + name))) << name;

  const json report = read_json(output + "/corner.json");
  EXPECT_EQ(report["joint"], "vertical 3");
  EXPECT_EQ(report["joint_law"], "rigid");
  EXPECT_DOUBLE_EQ(report["site"]["rounding_radius_m"].get<double>(), 0.05);
  // 3 zoom levels after the scene's mesh, unless converged earlier.
  const json &levels = report["levels"];
  ASSERT_GE(levels.size(), 2u);
  EXPECT_LE(levels.size(), 4u);
  EXPECT_EQ(report["converged"].get<bool>(), levels.size() < 4u)
    << report["stop_reason"];
  for (std::size_t k = 1; k < levels.size(); ++k)
    EXPECT_NEAR(levels[k]["cell_size_m"].get<double>(),
                0.5 * levels[k - 1]["cell_size_m"].get<double>(),
                1e-12 * levels[k - 1]["cell_size_m"].get<double>());
  // The peak is the largest nodal traction of the level's profile.
  const CsvTable traction = read_csv(output + "/corner_traction.csv");
  ASSERT_FALSE(traction.rows.empty());
  double largest = 0.;
  for (const auto &row : traction.rows)
    largest = std::max(largest, number_in(row, "normal_traction_Pa"));
  // The table leaves out a node at the end itself (distance 0), which the
  // peak counts where the zone ends on a node (a coarse level).
  const double peak = levels.back()["sigma_max_Pa"].get<double>();
  if (levels.back()["peak_distance_from_edge_m"].get<double>() > 0.)
    EXPECT_DOUBLE_EQ(largest, peak);
  else
    EXPECT_LE(largest, peak);

  const std::string kind = report["state"]["contact_kind"];
  EXPECT_TRUE(kind == "edge in fillet" || kind == "open at corner" ||
              kind == "reaches corner")
    << kind;
  if (kind == "edge in fillet")
    {
      EXPECT_TRUE(report["theory"]["covered"].get<bool>());
      EXPECT_NEAR(report["theory"]["exponent"].get<double>(), 1.5, 1e-6);
    }

  // Sorted by radius; the scene's own radius is its zoom's last level.
  const json &study = report["rounding_study"];
  ASSERT_EQ(study.size(), 2u);
  EXPECT_DOUBLE_EQ(study[0]["radius_m"].get<double>(), 0.02);
  EXPECT_DOUBLE_EQ(study[1]["radius_m"].get<double>(), 0.05);
  EXPECT_DOUBLE_EQ(study[1]["sigma_max_Pa"].get<double>(),
                   levels.back()["sigma_max_Pa"].get<double>());
  EXPECT_GT(study[0]["sigma_max_Pa"].get<double>(), 0.);
  EXPECT_TRUE(report["invariant_fit"].contains("exponent"));
  EXPECT_TRUE(report.contains("rounding_power_fitted"));
  EXPECT_TRUE(report.contains("sigma_max_falls_with_radius"));
  EXPECT_GT(report["closed_form"]["sigma_max_Pa"].get<double>(), 0.);
}

// The tool shall refuse a joint that does not exist, a rounding radius
// that does not fit the blocks and the rigid-block model, naming the
// parameter, with exit 2 and no results.
TEST(CornerCommand, RefusesBadInputBeforeWritingAnything)
{
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"--set Corner/Joint=4", "Corner/Joint"},
    {"--set \"Corner/Rounding radii=0.02, 0.9\"", "Corner/Rounding radii"},
    {"--set Model/Blocks=rigid", "Model/Blocks"}};
  for (const auto &[settings, parameter] : cases)
    {
      const std::string   output  = fresh_output_folder("corner_bad");
      const ProcessResult process = corner(output, settings);
      EXPECT_EQ(process.exit_code, 2) << settings << "\n" << process.output;
      EXPECT_NE(process.output.find(parameter), std::string::npos)
        << process.output;
      EXPECT_FALSE(std::filesystem::exists(output + "/corner.json"))
        << settings;
      EXPECT_FALSE(std::filesystem::exists(output + "/summary.json"))
        << settings;
    }
}
