// The exact (rigid) law on the default scene reaches the
// 1 % target, and its printed estimate brackets the converged face contact
// length. A long test (about 10 minutes on 2 cores; label "long"), built
// only with -DFLOORBLOCK_LONG_TESTS=ON and never by the README's test
// command: `ctest --test-dir build -L long`.
//
// The converged lengths are measured, not assumed (results/FINDINGS.md,
// section 7): at 30 deg 98.42 mm +- 0.03 mm (nested uniform
// ladder on a zone-graded mesh to 2.07 M DoFs, 98.4112 and 98.4163 mm on
// its last two levels; a degree-2 box at 1.08 M DoFs gave 98.44 mm); at
// vertical friction 60 deg the Richardson limits of two such ladders,
// 190.41 and 190.45 mm (finest levels 190.52 and 190.55 mm, still falling).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  /** summary.json's face-joint contact length estimate of one `run`. */
  json
  face_length_estimate(const std::string &name, const std::string &settings)
  {
    const std::string folder = fresh_output_folder(name);
    const auto        result =
      run_floorblock("run params/default.prm --output " + shell_quoted(folder) +
                     " --set Joints/Law=rigid " + settings);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    const json estimate =
      read_json(folder + "/summary.json")["fem_error_estimate"];
    EXPECT_TRUE(estimate["target"]["met"].get<bool>()) << estimate["target"];
    return estimate["joints"]["vertical 6"]["contact_length_m"];
  }

  /**
   * Expects [value - error, value + error] to hold the whole interval
   * [low, high] of the converged value, and the error within 1 %.
   */
  void
  expect_brackets(const json &length, const double low, const double high)
  {
    const double value = length["value"].get<double>();
    const double error = length["absolute_error"].get<double>();
    EXPECT_LE(value - error, low) << length;
    EXPECT_GE(value + error, high) << length;
    EXPECT_LE(length["relative_error"].get<double>(), 0.01) << length;
    EXPECT_LE(std::abs(value - 0.5 * (low + high)), 0.01 * low) << length;
  }
} // namespace

// The requirement of `run` with the exact law. On the mesh that
// Mesh/Cells per critical distance = 16 gives, the loop reports level 3's
// check, 98.23 mm +- 1.4 %, and stops at its 1800 s budget without meeting
// 1 % (results/FINDINGS.md, section 7), so this test fails there.
TEST(ExactLawAccuracy, DefaultSceneMeetsOnePercentAndBracketsTheConvergedLength)
{
  expect_brackets(face_length_estimate("exact_law_default", ""),
                  0.09839,
                  0.09845);
}

// Level 3, 190.37 mm; its check agreed to
// 0.005 mm, and the estimate is the range of levels 2, 3 and the check
// (0.16 mm), as the check reversed the change from level 2.
TEST(ExactLawAccuracy, VerticalFrictionSixtyBracketsTheRichardsonLimits)
{
  expect_brackets(face_length_estimate("exact_law_friction_60",
                                       "--set 'Joints/Vertical friction "
                                       "angle=60'"),
                  0.19041,
                  0.19045);
}
