// Issue #7: a run that does not converge keeps its last converged increment,
// writes summary.json whose status says "not converged" and why, exits with
// code 1, and never writes NaN or inf. Forced here by allowing the uplift
// stage one increment, no cutback and 6 Newton iterations (the gravity and
// support-load stages converge within 6 on this scene; the uplift does not).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  const std::string starved_uplift =
    " --set \"Solver/Uplift steps=1\" --set \"Solver/Max cutbacks=0\""
    " --set \"Solver/Max Newton iterations=6\"";
} // namespace

TEST(NotConverged, RunKeepsLastConvergedIncrementAndSaysWhy)
{
  const std::string folder = fresh_output_folder("run_not_converged");
  const auto        result =
    run_floorblock("run tests/scenarios/three_blocks.prm" + starved_uplift +
                   " --output " + shell_quoted(folder));
  EXPECT_EQ(result.exit_code, 1) << result.output;

  ASSERT_TRUE(std::filesystem::exists(folder + "/summary.json"));
  const std::string summary_text = read_text(folder + "/summary.json");
  const json        summary      = json::parse(summary_text);
  EXPECT_EQ(summary["status"], "not converged");
  const std::string why = summary["status_text"].get<std::string>();
  EXPECT_NE(why.find("uplift"), std::string::npos) << why;
  EXPECT_NE(why.find("tried"), std::string::npos) << why;

  // The last converged increment (end of the support-load stage) is kept
  // and compared; the sizes are reported although the solve failed.
  const json &fem = summary["fem"];
  EXPECT_GE(fem["n_increments"].get<int>(), 1);
  EXPECT_GT(fem["n_dofs"].get<int>(), 0);
  EXPECT_FALSE(summary["comparison"]["final"].empty());
  EXPECT_TRUE(std::filesystem::exists(folder + "/report.md"));

  for (const std::string name : {"summary.json", "fem.json", "joints.csv"})
    EXPECT_FALSE(has_non_finite_value(read_text(folder + "/" + name))) << name;
  // summary.json has nulls only where a closed form has no answer, each with
  // a status; the FEM's own numbers are never null.
  EXPECT_EQ(read_text(folder + "/fem.json").find("null"), std::string::npos);

  // The failed attempt is listed and the counters say what they cover:
  // every converged increment (1 gravity + 2 support), the failed
  // attempt's Newton iterations (at most Solver/Max Newton iterations = 6),
  // and linear solves for all of them.
  ASSERT_TRUE(fem.contains("failure"));
  EXPECT_EQ(fem["failure"]["failed_attempts"].size(), 1u);
  EXPECT_EQ(fem["failure"]["cutbacks_before_failure"], 0);
  EXPECT_EQ(fem["n_increments"].get<int>(), 3);
  const unsigned int failed_newton =
    fem["failure"]["failed_newton_iterations"].get<unsigned int>();
  EXPECT_GE(failed_newton, 1u);
  EXPECT_LE(failed_newton, 6u);
  EXPECT_GE(fem["linear_solves"].get<unsigned int>(),
            fem["newton_iterations"].get<unsigned int>() + failed_newton);
}

TEST(NotConverged, NothingConvergedStillWritesAnHonestSummary)
{
  const std::string folder = fresh_output_folder("run_nothing_converged");
  const auto        result = run_floorblock(
    "run tests/scenarios/three_blocks.prm --set \"Solver/Max cutbacks=0\""
           " --set \"Solver/Max Newton iterations=2\" --output " +
    shell_quoted(folder));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_EQ(result.output.find("wrote " + folder + "/report.md"),
            std::string::npos)
    << "claims a report that was not written:\n"
    << result.output;
  const json summary = json::parse(read_text(folder + "/summary.json"));
  EXPECT_EQ(summary["status"], "not converged");
  EXPECT_EQ(summary["fem"]["n_increments"], 0);
  EXPECT_FALSE(std::filesystem::exists(folder + "/report.md"));
}
