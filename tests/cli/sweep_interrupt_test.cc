#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  // Four small FEM cases of Figure 6.5 on the 3-block test scene.
  const std::string sweep_arguments =
    "sweep tests/scenarios/three_blocks.prm --fem --figure fig6_5 --limit 4";

  std::vector<std::filesystem::path>
  files_in(const std::string &folder)
  {
    std::vector<std::filesystem::path> files;
    if (std::filesystem::exists(folder))
      for (const auto &entry : std::filesystem::directory_iterator(folder))
        files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
  }

  unsigned int
  count_case_files(const std::string &folder)
  {
    unsigned int n = 0;
    for (const auto &file : files_in(folder + "/cases"))
      n += file.extension() == ".json" && file.filename().string()[0] != '.';
    return n;
  }

  /// A case record without its timing, which differs from run to run.
  json
  without_timing(const std::filesystem::path &path)
  {
    std::ifstream in(path);
    json          record = json::parse(in);
    record["fem"].erase("wall_time_s");
    return record;
  }
} // namespace

// The tool shall stop a sweep cleanly on SIGINT, keep the finished cases,
// leave nothing of the running one, and on resume compute only the rest,
// ending with the same results as an uninterrupted sweep.
TEST(SweepInterrupt, ResumesWithOnlyTheMissingCases)
{
  const std::string reference = fresh_output_folder("sweep_reference");
  const auto        full =
    run_floorblock(sweep_arguments + " --output " + shell_quoted(reference));
  ASSERT_EQ(full.exit_code, 0) << full.output;
  ASSERT_EQ(count_case_files(reference), 4u);

  const std::string interrupted = fresh_output_folder("sweep_interrupted");
  const std::string log         = interrupted + ".log";
  const int         process =
    start_floorblock(sweep_arguments + " --output " + shell_quoted(interrupted),
                     log);
  // Interrupt as soon as two cases are finished (bounded wait: 5 minutes).
  const auto give_up =
    std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (count_case_files(interrupted) < 2 &&
         std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ::kill(process, SIGINT);
  const int interrupted_exit = wait_for_exit(process);

  EXPECT_EQ(interrupted_exit, 130) << read_text(log);
  const unsigned int kept = count_case_files(interrupted);
  EXPECT_GE(kept, 2u);
  EXPECT_LT(kept, 4u) << "the sweep finished before the signal took effect";
  for (const auto &file : files_in(interrupted + "/cases"))
    EXPECT_EQ(file.extension(), ".json") << "partial file left: " << file;
  EXPECT_FALSE(std::filesystem::exists(interrupted + "/sweep_fem_fig6_5.csv"));

  const auto resumed =
    run_floorblock(sweep_arguments + " --output " + shell_quoted(interrupted));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  // Each computed case prints one progress line naming how many were reused.
  std::size_t computed = 0;
  for (std::size_t at = resumed.output.find("cases done");
       at != std::string::npos;
       at = resumed.output.find("cases done", at + 1))
    ++computed;
  EXPECT_EQ(computed, 4u - kept) << resumed.output;

  const auto reference_files = files_in(reference + "/cases");
  const auto resumed_files   = files_in(interrupted + "/cases");
  ASSERT_EQ(reference_files.size(), resumed_files.size());
  for (std::size_t k = 0; k < reference_files.size(); ++k)
    {
      EXPECT_EQ(reference_files[k].filename(), resumed_files[k].filename());
      EXPECT_EQ(without_timing(reference_files[k]),
                without_timing(resumed_files[k]))
        << reference_files[k].filename();
    }
  EXPECT_EQ(read_text(reference + "/sweep_fem_fig6_5.csv"),
            read_text(interrupted + "/sweep_fem_fig6_5.csv"));
}
