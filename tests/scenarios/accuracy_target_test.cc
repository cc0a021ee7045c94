// Issue 14, accuracy as the input, on a scene whose level 0 is far from
// the target: `run` must refine until the face joint's Q and contact length
// are estimated within 1 %, and the estimate must bracket the converged
// value. Release only (scenario label): about 30 s, 124k DoFs in the last
// check, too slow under the sanitizers' debug deal.II.
#include "process.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>

using namespace FloorBlockTest;
using nlohmann::json;

// The tool shall meet the 1 % target on the 3-block scene (sharp corners,
// 1066 DoFs at level 0) with an estimate that brackets the converged face
// joint: `converge --mode uniform --levels 5`, level 4 (226k DoFs):
// 684.17 mm and 3722.53 kN/m (levels 2-4: 683.65, 683.84, 684.17 mm).
TEST(AccuracyTarget, ThreeBlocksMeetOnePercentWithAnEstimateThatBrackets)
{
  const std::string folder = fresh_output_folder("accuracy_three_blocks");
  const auto        result = run_floorblock(
    "run tests/scenarios/three_blocks.prm --output " + shell_quoted(folder) +
    " --set 'Solver/Error estimate=refined solve'");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const json  summary  = read_json(folder + "/summary.json");
  const json &estimate = summary["fem_error_estimate"];
  ASSERT_TRUE(estimate["target"]["met"].get<bool>()) << estimate["target"];
  EXPECT_GT(estimate["target"]["reported_level"].get<unsigned int>(), 0u);

  const json &face = estimate["joints"]["vertical 3"];
  const std::pair<const char *, double> converged[] = {
    {"normal_force_N_per_m", 3.722527599e+06},
    {"contact_length_m", 6.841650920e-01}};
  for (const auto &[figure, reference] : converged)
    {
      const double value = face[figure]["value"].get<double>();
      const double error = face[figure]["absolute_error"].get<double>();
      EXPECT_LE(error, 0.01 * std::abs(face[figure]["refined_value"].get<double>()))
        << figure;
      EXPECT_LE(std::abs(value - reference), error)
        << figure << ": value " << value << ", estimate " << error;
      // Within the target of the converged value, too.
      EXPECT_LE(std::abs(value - reference), 0.01 * reference) << figure;
    }
}
