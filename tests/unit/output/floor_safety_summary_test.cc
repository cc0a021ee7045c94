// The floor safety in run's outputs (output/floor_safety_summary): the
// verdict's method per joint law, and the report's table at the factor's
// cap.

#include <output/floor_safety_summary.h>

#include <gtest/gtest.h>

using namespace FloorBlock;

namespace
{
  /** A resolved corner with the given factors and verdict method. */
  Safety::CornerSafety
  corner(const std::string         &block,
         const double               point,
         const double               line,
         const double               area,
         const Safety::SafetyMethod method)
  {
    Safety::CornerSafety result;
    result.path.joint_name   = "vertical 6";
    result.path.block        = block;
    result.critical_distance = 0.02;
    result.largest_cell      = 0.001;
    result.point_factor      = point;
    result.line_factor       = line;
    result.area_factor       = area;
    result.verdict_method    = method;
    return result;
  }
} // namespace

// With exact contact the governing corner is the smallest area factor and
// summary.json names the method; the line method would have chosen the
// other corner.
TEST(FloorSafetySummary, ExactContactGoesByTheAreaFactor)
{
  const auto                              area    = Safety::SafetyMethod::area;
  const std::vector<Safety::CornerSafety> corners = {
    corner("block 6", 0.5, 0.6, 0.9, area),
    corner("face block", 0.7, 0.8, 0.85, area)};
  const Scene::ClosedForms closed_forms{};
  const auto               summary =
    Output::floor_safety_summary_json(corners, std::nullopt, closed_forms);
  EXPECT_EQ(summary["verdict_method"], "area");
  EXPECT_EQ(summary["governing"]["corner"], "face block at vertical 6");
  EXPECT_EQ(summary["status"], "fails");
}

// A factor at the cap (an almost unloaded corner) says "at least" and
// carries no error in report.md; the others are written to three digits.
TEST(FloorSafetySummary, ReportTableSaysAtLeastAtTheCap)
{
  const auto                              line    = Safety::SafetyMethod::line;
  const std::vector<Safety::CornerSafety> corners = {
    corner("block 2",
           Strength::largest_strength_factor,
           Strength::largest_strength_factor,
           Strength::largest_strength_factor,
           line),
    corner("face block", 0.746, 0.928, 0.992, line)};
  const Scene::ClosedForms closed_forms{};
  const std::string        report =
    Output::floor_safety_markdown(corners, std::nullopt, closed_forms);
  EXPECT_NE(report.find(
              "| block 2 at vertical 6 | >= 100 (almost unloaded) | |"),
            std::string::npos)
    << report;
  EXPECT_NE(
    report.find(
      "| face block at vertical 6 | 0.746 | (error not estimated) | 0.928 |"),
    std::string::npos)
    << report;
  EXPECT_NE(report.find("the verdict goes by the line method"),
            std::string::npos);
}
