// Randomized robustness test of scene reading, validation and the closed
// forms: every input must end in InputError or in finite, well-formed output.

#include <deal.II/base/exceptions.h>

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <typeinfo>

#include "fuzz_settings.h"
#include "output_checks.h"
#include "scene_pipeline.h"
#include "scene_text_generator.h"

using namespace FloorBlock::Fuzz;

namespace
{
  // Fixed seed: ctest runs repeat exactly. 2000 inputs take a few seconds
  // in Release; .ci/fuzz.sh runs more with changing seeds.
  constexpr std::uint64_t default_seed     = 20261121;
  constexpr std::uint64_t default_n_inputs = 2000;
  // Failures printed in full; the rest are only counted.
  constexpr std::size_t n_failures_shown = 10;

  std::string
  default_scene_text()
  {
    std::ifstream     file(std::string(FLOORBLOCK_SOURCE_DIR) +
                       "/params/default.prm");
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
  }

  /** A private folder for scene files, removed when the test ends. */
  class WorkDirectory
  {
  public:
    WorkDirectory()
      : path(std::filesystem::temp_directory_path() /
             ("floorblock_fuzz_" + std::to_string(::getpid())))
    {
      std::filesystem::create_directories(path);
    }
    ~WorkDirectory()
    {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
    const std::filesystem::path path;
  };

  std::filesystem::path
  reproducer_folder()
  {
    return std::filesystem::temp_directory_path() / "floorblock_fuzz_failures";
  }

  /** Saves an input where a developer can rerun it; returns the scene path. */
  std::string
  save_reproducer(const SceneInput &input, const std::string &name)
  {
    const auto folder = reproducer_folder();
    std::filesystem::create_directories(folder);
    const auto scene = folder / (name + input.extension);
    std::ofstream(scene, std::ios::binary) << input.text;
    std::ofstream overrides(folder / (name + ".overrides"), std::ios::binary);
    for (const std::string &assignment : input.overrides)
      overrides << assignment << '\n';
    return scene.string();
  }

  /**
   * Keeps the input that is running on disk until it returns: an input that
   * aborts the process (a failed assertion in a library, a sanitizer
   * report) leaves no other trace of itself, and the message printed at
   * the start says where to find it.
   */
  class InputInProgress
  {
  public:
    explicit InputInProgress(const std::uint64_t seed)
      : name("running_seed" + std::to_string(seed) + "_pid" +
             std::to_string(::getpid()))
    {
      std::cout << "[fuzz] each input is saved as "
                << (reproducer_folder() / name).string()
                << ".* while it runs; after a crash that file reproduces it"
                << std::endl; // flushed: an abort discards buffered output
    }
    ~InputInProgress()
    {
      remove_files();
    }
    void
    save(const SceneInput &input) const
    {
      remove_files(); // the previous input may have had another extension
      save_reproducer(input, name);
    }

  private:
    void
    remove_files() const
    {
      std::error_code ignored;
      for (const char *extension : {".prm", ".json", ".xml", ".overrides"})
        std::filesystem::remove(reproducer_folder() / (name + extension),
                                ignored);
    }

    const std::string name;
  };

  /**
   * An error message without the scene path, up to the first digit (values
   * start there): groups rejections by reason for the summary.
   */
  std::string
  rejection_reason(const std::string &message)
  {
    constexpr std::size_t longest_reason = 90;
    std::string           reason         = message;
    if (!reason.empty() && reason.front() == '/')
      reason.erase(0, reason.find(": ") + 2);
    return reason.substr(0,
                         std::min(reason.find_first_of("0123456789"),
                                  longest_reason));
  }

  /** Runs one input; returns "" or what went wrong, in one paragraph. */
  std::string
  failure_of(const SceneInput                     &input,
             const WorkDirectory                  &work,
             bool                                 &accepted,
             std::map<std::string, std::uint64_t> &n_by_reason)
  {
    std::string problem;
    try
      {
        const PipelineResult result = run_scene_pipeline(input.text,
                                                         input.extension,
                                                         input.overrides,
                                                         work.path);
        accepted                    = result.accepted;
        if (!accepted)
          ++n_by_reason[rejection_reason(result.error_message)];
        for (const std::string &defect : result.defects)
          problem += "\n  " + defect;
      }
    catch (const dealii::ExceptionBase &error)
      {
        // deal.II's what() is empty until printed; print_info has the text.
        std::ostringstream info;
        error.print_info(info);
        problem = std::string("\n  escaped deal.II exception ") +
                  error.get_exc_name() + " (not InputError): " + info.str();
      }
    catch (const std::exception &error)
      {
        problem = std::string("\n  escaped exception ") + typeid(error).name() +
                  " (not InputError): " + error.what();
      }
    catch (...)
      {
        problem = "\n  escaped a non-std exception";
      }
    return problem;
  }
} // namespace

// The tool shall read its default scene and produce clean closed forms.
TEST(SceneFuzz, DefaultSceneIsAcceptedAndClean)
{
  WorkDirectory        work;
  const PipelineResult result =
    run_scene_pipeline(default_scene_text(), ".prm", {}, work.path);
  EXPECT_TRUE(result.accepted) << result.error_message;
  EXPECT_TRUE(result.defects.empty()) << result.defects.front();
}

// The tool shall refuse "include" statements in scene files with InputError:
// deal.II follows them anywhere; before the fix, including the scene itself
// crashed with a stack overflow and including /dev/zero hung.
TEST(SceneFuzz, IncludeStatementsAreRejected)
{
  WorkDirectory     work;
  const std::string self = (work.path / "scene.prm").string();
  for (const std::string &statement : {"include " + self,
                                       std::string("include /dev/zero"),
                                       std::string("INCLUDE /tmp"),
                                       std::string("  include   /dev/null # x"),
                                       std::string("incl\\\nude /dev/zero")})
    {
      const PipelineResult result = run_scene_pipeline(
        default_scene_text() + statement + "\n", ".prm", {}, work.path);
      EXPECT_FALSE(result.accepted) << statement;
      EXPECT_NE(result.error_message.find("include"), std::string::npos)
        << statement << ": " << result.error_message;
    }
}

// The checks themselves shall catch non-finite numbers and unknown statuses,
// so that a clean fuzz run means something.
TEST(SceneFuzz, ChecksDetectNonFiniteOutput)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(json_defects({{"Q", {1.0, nan}}}).empty());
  EXPECT_FALSE(json_defects({{"sigma", nullptr}}).empty());
  EXPECT_FALSE(json_defects({{"status", "no_such_status"}}).empty());
  EXPECT_TRUE(json_defects({{"status", "ok"}, {"Q", {1.0, 2.0}}}).empty());

  const std::string header = "block,Q,no_rotation_status\n";
  EXPECT_FALSE(csv_defects(header + "1,nan,ok\n").empty());
  EXPECT_FALSE(csv_defects(header + "1,1.0e+00,broken\n").empty());
  EXPECT_FALSE(csv_defects(header + "1,1.0e+00\n").empty());
  EXPECT_TRUE(csv_defects(header + "1,,self_locking\n").empty());

  EXPECT_FALSE(table_defects("Q = -inf kN").empty());
  EXPECT_FALSE(table_defects("sigma = nan MPa").empty());
  EXPECT_TRUE(table_defects("so Q would be infinite.").empty());
}

// The tool shall answer any scene file and any --set override with either a
// clean InputError or finite, well-formed results: no crash, no other
// exception, no NaN/inf in analytic.json, analytic.csv or the table.
TEST(SceneFuzz, RandomScenesGiveInputErrorOrFiniteOutput)
{
  const FuzzSettings settings = fuzz_settings(default_seed, default_n_inputs);
  const SceneTextGenerator generator(default_scene_text());
  RandomEngine             engine(settings.seed);
  WorkDirectory            work;

  std::array<std::uint64_t, n_input_kinds> n_accepted{}, n_rejected{};
  std::uint64_t                            n_failures = 0;
  std::map<std::string, std::uint64_t>     n_by_reason;
  const InputInProgress                    in_progress(settings.seed);
  for (std::uint64_t index = 0; index < settings.n_inputs; ++index)
    {
      const SceneInput input = generator.next(engine);
      in_progress.save(input);
      bool              accepted = false;
      const std::string problem =
        failure_of(input, work, accepted, n_by_reason);
      const auto kind = static_cast<unsigned int>(input.kind);
      ++(accepted ? n_accepted : n_rejected)[kind];
      if (problem.empty())
        continue;
      if (++n_failures <= n_failures_shown)
        ADD_FAILURE() << "seed " << settings.seed << " input " << index << " ("
                      << to_string(input.kind) << "), saved as "
                      << save_reproducer(input,
                                         "seed" +
                                           std::to_string(settings.seed) +
                                           "_input" + std::to_string(index))
                      << problem;
    }
  EXPECT_EQ(n_failures, 0u);

  std::uint64_t total_accepted = 0;
  for (unsigned int kind = 0; kind < n_input_kinds; ++kind)
    {
      std::cout << "[fuzz] " << to_string(static_cast<InputKind>(kind))
                << ": accepted " << n_accepted[kind] << ", rejected "
                << n_rejected[kind] << '\n';
      total_accepted += n_accepted[kind];
    }
  // The most frequent rejection reasons show what the inputs exercise.
  std::vector<std::pair<std::uint64_t, std::string>> reasons;
  for (const auto &[reason, count] : n_by_reason)
    reasons.emplace_back(count, reason);
  std::sort(reasons.rbegin(), reasons.rend());
  constexpr std::size_t n_reasons_shown = 12;
  for (std::size_t i = 0; i < std::min(reasons.size(), n_reasons_shown); ++i)
    std::cout << "[fuzz] rejected " << reasons[i].first
              << " x: " << reasons[i].second << '\n';
  std::cout << "[fuzz] seed " << settings.seed << ": " << settings.n_inputs
            << " scene inputs tried, " << total_accepted << " accepted, "
            << n_failures << " failures\n";
  // A run that rejects (almost) everything never reaches the closed forms
  // and would pass vacuously.
  if (settings.n_inputs >= 1000)
    {
      EXPECT_GT(total_accepted, settings.n_inputs / 10);
    }
}
