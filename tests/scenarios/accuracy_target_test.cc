// Issue 14, accuracy as the input, on a scene whose level 0 is far from
// the target: `run` must refine until the face joint's Q and contact length
// are estimated within 1 %, and the estimate must bracket the converged
// value. Release only (scenario label): about 30 s, 124k DoFs in the last
// check, too slow under the sanitizers' debug deal.II.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

#include "estimate_checks.h"
#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

// The tool shall meet the 1 % target on the 3-block scene (sharp corners,
// 1066 DoFs at level 0) with an estimate that brackets the converged face
// joint (three_blocks_converged_face). With Solver/FE degree = auto (the
// default) degree 1's level 0 misses (2.5 %), degree 2 joins, and its
// level 0's check meets, confirmed by its level 1, after about 5 s of its
// solves; degree 1 alone needs 7 levels and about 40 s.
TEST(AccuracyTarget, ThreeBlocksMeetOnePercentWithAnEstimateThatBrackets)
{
  const std::string folder = fresh_output_folder("accuracy_three_blocks");
  const auto        result = run_floorblock(
    "run tests/scenarios/three_blocks.prm --output " + shell_quoted(folder) +
    " --set 'Solver/Error estimate=refined solve'");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const json  summary  = read_json(folder + "/summary.json");
  const json &estimate = summary["fem_error_estimate"];
  const json &target   = estimate["target"];
  ASSERT_TRUE(target["met"].get<bool>()) << target;
  // The race: the reported solve is degree 2's, degree 1's record is kept.
  EXPECT_EQ(target["fe_degree"].get<unsigned int>(), 2u);
  EXPECT_NE(target["fe_degree_choice"].get<std::string>().find(
              "degree 2 met the target first"),
            std::string::npos);
  ASSERT_EQ(target["other_fe_degrees"].size(), 1u);
  const json &degree_1 = target["other_fe_degrees"][0];
  EXPECT_EQ(degree_1["fe_degree"].get<unsigned int>(), 1u);
  EXPECT_FALSE(degree_1["met"].get<bool>());
  EXPECT_GT(degree_1["levels"][0]["worst_target_relative_error"].get<double>(),
            0.01);
  // Both loops record their own solving time, and neither got more than
  // one step ahead of the other: degree 1 stepped last while it had spent
  // less than degree 2, which then needed one more step (its confirming
  // level) to win.
  const double degree_1_time = degree_1["wall_time_s"].get<double>();
  const double degree_2_time = target["wall_time_s"].get<double>();
  EXPECT_GT(degree_1_time, 0.);
  const json &last = degree_1["levels"].back();
  EXPECT_LE(degree_1_time - last["wall_time_s"].get<double>() -
              last["halved_wall_time_s"].get<double>(),
            degree_2_time);
  // Confirmed by the next adaptive level of degree 2.
  const unsigned int confirming =
    target["confirming_level"].get<unsigned int>();
  EXPECT_EQ(confirming, target["reported_level"].get<unsigned int>() + 1);
  EXPECT_EQ(target["levels"].size(), confirming + 1);
  // The reported files are degree 2's: fem.json has the reported DoFs.
  const json &reported =
    target["levels"][target["reported_level"].get<unsigned int>()];
  EXPECT_EQ(read_json(folder + "/fem.json")["n_dofs"].get<unsigned int>(),
            target["reported_solve"].get<std::string>() == "refined" ?
              reported["halved_n_dofs"].get<unsigned int>() :
              reported["n_dofs"].get<unsigned int>());

  const json &face = estimate["joints"]["vertical 3"];
  expect_estimates_bracket(face, three_blocks_converged_face);
  for (const auto &[figure, reference] : three_blocks_converged_face)
    {
      const double value = face[figure]["value"].get<double>();
      // The estimate is within the target, and so is the value.
      EXPECT_LE(face[figure]["absolute_error"].get<double>(),
                0.01 * std::abs(face[figure]["refined_value"].get<double>()))
        << figure;
      EXPECT_LE(std::abs(value - reference), 0.01 * reference) << figure;
    }
}

// The same scene with a 2 % target meets it on level 0's check: level 0's
// own estimate (6 times the difference) is 2.5 %, the check's (3 times)
// 1.2 %. The tool shall then report the check's figures (683.8 mm on 3866
// DoFs), its files and its estimate, and that estimate must bracket the
// converged face joint too.
TEST(AccuracyTarget, ThreeBlocksMeetTwoPercentWithLevelZerosCheck)
{
  const std::string folder = fresh_output_folder("accuracy_three_blocks_2");
  const auto        result = run_floorblock(
    "run tests/scenarios/three_blocks.prm --output " + shell_quoted(folder) +
    " --set 'Solver/Error estimate=refined solve'"
           " --set 'Solver/FE degree=1'"
           " --set 'Mesh/Target relative error=0.02'");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const json  summary  = read_json(folder + "/summary.json");
  const json &estimate = summary["fem_error_estimate"];
  const json &target   = estimate["target"];
  ASSERT_TRUE(target["met"].get<bool>()) << target;
  EXPECT_EQ(target["reported_level"].get<unsigned int>(), 0u);
  EXPECT_EQ(target["reported_solve"].get<std::string>(), "refined");
  EXPECT_GT(target["levels"][0]["worst_target_relative_error"].get<double>(),
            0.02);
  EXPECT_EQ(read_json(folder + "/fem.json")["n_dofs"].get<unsigned int>(),
            target["levels"][0]["halved_n_dofs"].get<unsigned int>());

  const json &face = estimate["joints"]["vertical 3"];
  expect_estimates_bracket(face, three_blocks_converged_face);
  for (const auto &[figure, reference] : three_blocks_converged_face)
    {
      // The reported value is the check's.
      EXPECT_EQ(face[figure]["value"].get<double>(),
                face[figure]["refined_value"].get<double>())
        << figure;
      EXPECT_LE(face[figure]["absolute_error"].get<double>(),
                0.02 * std::abs(face[figure]["refined_value"].get<double>()))
        << figure;
      EXPECT_LE(std::abs(face[figure]["value"].get<double>() - reference),
                0.02 * reference)
        << figure;
    }
}
