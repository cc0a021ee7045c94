#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  // Six FEM cases (four on a Latin hypercube, one near FS = 1, one held
  // out) of two uncertain inputs on a three-block scene: under a second
  // each.
  const std::string assess_arguments = "assess tests/cli/assess_scene.prm";

  std::vector<std::filesystem::path>
  case_files(const std::string &folder)
  {
    std::vector<std::filesystem::path> files;
    if (std::filesystem::exists(folder + "/assess_cases"))
      for (const auto &entry :
           std::filesystem::directory_iterator(folder + "/assess_cases"))
        if (entry.path().extension() == ".json")
          files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
  }

  /// A case record without its timing, which differs from run to run.
  json
  record_without_timing(const std::filesystem::path &path)
  {
    json record = read_json(path.string());
    record.erase("wall_time_s");
    return record;
  }

  /// assess.json without the costs, which hold timings.
  json
  answer_of(const std::string &folder)
  {
    json answer = read_json(folder + "/assess.json");
    answer.erase("cost_by_model");
    return answer;
  }
} // namespace

// The tool shall answer P(FS < 1) with its interval, the surrogate's error,
// Sobol' indices per input and the cases that built them.
TEST(Assess, WritesTheProbabilityWithItsIntervalAndTheCases)
{
  const std::string output = fresh_output_folder("assess");
  const auto        run =
    run_floorblock(assess_arguments + " --output " + shell_quoted(output));
  ASSERT_EQ(run.exit_code, 0) << run.output;

  const json   answer = read_json(output + "/assess.json");
  const json  &pf     = answer.at("failure_probability");
  const double p      = pf.at("estimate").get<double>();
  EXPECT_GE(p, 0.);
  EXPECT_LE(p, 1.);
  EXPECT_LE(pf.at("half_width_95").get<double>(), 0.01);
  EXPECT_GT(pf.at("half_width_95").get<double>(), 0.);
  EXPECT_LE(pf.at("interval_95")[0].get<double>(), p);
  EXPECT_GE(pf.at("interval_95")[1].get<double>(), p);
  // Shifting FS by the surrogate's error moves P_f to either side of it.
  const json &shifted = pf.at("with_surrogate_error");
  EXPECT_LE(shifted.at("P_FS_times_exp_error_below_1").get<double>(), p);
  EXPECT_GE(shifted.at("P_FS_over_exp_error_below_1").get<double>(), p);

  for (const std::string order : {"first_order", "total_order"})
    for (const std::string input :
         {"Joints/Bedding friction angle", "Strength/Intact UCS"})
      {
        const json &index = answer.at("sobol_indices").at(order).at(input);
        EXPECT_LE(index.at("interval_95")[0].get<double>(),
                  index.at("interval_95")[1].get<double>());
      }
  EXPECT_EQ(answer.at("fem_cases").at("training").at("total"), 5);
  EXPECT_EQ(answer.at("fem_cases").at("validation").at("total"), 1);
  EXPECT_EQ(answer.at("surrogate").at("held_out").at("cases"), 1);
  EXPECT_GT(answer.at("surrogate").at("stated_error").get<double>(), 0.);

  const CsvTable cases = read_csv(output + "/cases.csv");
  ASSERT_EQ(cases.rows.size(), 6u);
  EXPECT_NE(std::find(cases.columns.begin(),
                      cases.columns.end(),
                      "Strength/Intact UCS (Pa)"),
            cases.columns.end());
  std::map<std::string, int> roles;
  for (const CsvRow &row : cases.rows)
    ++roles[row.at("role")];
  EXPECT_EQ(roles,
            (std::map<std::string, int>{{"training", 4},
                                        {"refinement1", 1},
                                        {"validation", 1}}));
  for (const CsvRow &row : cases.rows)
    {
      EXPECT_EQ(row.at("model"), "fem");
      EXPECT_EQ(row.at("status"), "solved") << row.at("message");
      // Compliant joints: the verdict goes by the line method.
      EXPECT_EQ(row.at("verdict_method"), "line");
      EXPECT_EQ(row.at("FS"), row.at("FS_line"));
      const double ucs = std::stod(row.at("Strength/Intact UCS (Pa)"));
      EXPECT_GE(ucs, 10e6);
      EXPECT_LE(ucs, 100e6);
    }
}

// The tool shall stop on SIGINT keeping the finished cases, and a rerun
// shall compute only the others and give the uninterrupted run's answer.
TEST(Assess, ResumesAfterAnInterruptionWithoutRecomputing)
{
  const std::string reference = fresh_output_folder("assess_reference");
  const auto        full =
    run_floorblock(assess_arguments + " --output " + shell_quoted(reference));
  ASSERT_EQ(full.exit_code, 0) << full.output;
  ASSERT_EQ(case_files(reference).size(), 6u);

  const std::string interrupted = fresh_output_folder("assess_interrupted");
  const int         process = start_floorblock(assess_arguments + " --output " +
                                         shell_quoted(interrupted),
                                       interrupted + ".log");
  const auto        give_up =
    std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (case_files(interrupted).size() < 3 &&
         std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ::kill(process, SIGINT);
  EXPECT_EQ(wait_for_exit(process), 130) << read_text(interrupted + ".log");
  const std::size_t kept = case_files(interrupted).size();
  EXPECT_GE(kept, 3u);
  EXPECT_LT(kept, 6u) << "the study finished before the signal took effect";
  EXPECT_FALSE(std::filesystem::exists(interrupted + "/assess.json"));

  const auto resumed =
    run_floorblock(assess_arguments + " --output " + shell_quoted(interrupted));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  std::size_t computed = 0;
  for (std::size_t at = resumed.output.find("cases done");
       at != std::string::npos;
       at = resumed.output.find("cases done", at + 1))
    ++computed;
  EXPECT_EQ(computed, 6u - kept) << resumed.output;
  EXPECT_EQ(read_json(interrupted + "/assess.json")
              .at("cost_by_model")[0]
              .at("from_earlier_runs"),
            kept);

  const auto reference_files = case_files(reference);
  const auto resumed_files   = case_files(interrupted);
  ASSERT_EQ(reference_files.size(), resumed_files.size());
  for (std::size_t k = 0; k < reference_files.size(); ++k)
    EXPECT_EQ(record_without_timing(reference_files[k]),
              record_without_timing(resumed_files[k]))
      << reference_files[k].filename();
  EXPECT_EQ(answer_of(reference), answer_of(interrupted));
}

// A folder holding another scene's cases is refused before anything runs.
TEST(Assess, RefusesAFolderOfAnotherScene)
{
  const std::string output = fresh_output_folder("assess_other_scene");
  std::filesystem::create_directories(output + "/assess_cases");
  {
    std::ofstream other(output + "/assess_cases/scene.prm");
    other << "subsection Geometry\n  set Number of blocks = 5\nend\n";
  }
  const auto run =
    run_floorblock(assess_arguments + " --output " + shell_quoted(output));
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("records other scene parameters"),
            std::string::npos)
    << run.output;
  EXPECT_EQ(case_files(output).size(), 0u);
}
