// Issue #7: a run that does not converge keeps its last converged increment,
// writes summary.json whose status says "not converged" and why, exits with
// code 1, and never writes NaN or inf. Forced here by allowing the uplift
// stage one increment, no cutback and 6 Newton iterations (the gravity and
// support-load stages converge within 6 on this scene; the uplift does not).
#include "process.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  std::string
  text_of(const std::string &path)
  {
    std::ifstream      in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  const std::string starved_uplift =
    " --set \"Solver/Uplift steps=1\" --set \"Solver/Max cutbacks=0\""
    " --set \"Solver/Max Newton iterations=6\"";
} // namespace

TEST(NotConverged, RunKeepsLastConvergedIncrementAndSaysWhy)
{
  const std::string folder = fresh_output_folder("run_not_converged");
  const auto        result = run_floorblock(
    "run tests/scenarios/three_blocks.prm" + starved_uplift + " --output " +
    shell_quoted(folder));
  EXPECT_EQ(result.exit_code, 1) << result.output;

  ASSERT_TRUE(std::filesystem::exists(folder + "/summary.json"));
  const std::string summary_text = text_of(folder + "/summary.json");
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

  // nlohmann writes NaN/inf as null, fmt as "nan"/"inf": neither may appear
  // as a value (words like "information" may).
  const std::regex non_finite("(^|[^A-Za-z])-?(nan|inf)([^A-Za-z]|$)",
                              std::regex::icase);
  for (const std::string name : {"summary.json", "fem.json", "joints.csv"})
    {
      const std::string text = text_of(folder + "/" + name);
      EXPECT_FALSE(std::regex_search(text, non_finite)) << name;
    }
  // summary.json has nulls only where a closed form has no answer, each with
  // a status; the FEM's own numbers are never null.
  EXPECT_EQ(text_of(folder + "/fem.json").find("null"), std::string::npos);
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
    << "claims a report that was not written:\n" << result.output;
  const json summary = json::parse(text_of(folder + "/summary.json"));
  EXPECT_EQ(summary["status"], "not converged");
  EXPECT_EQ(summary["fem"]["n_increments"], 0);
  EXPECT_FALSE(std::filesystem::exists(folder + "/report.md"));
}
