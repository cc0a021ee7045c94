#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "process.h"

using namespace FloorBlockTest;

namespace
{
  /**
   * Runs `floorblock verify <name>`, expects exit 0 and returns verify.json.
   * Each case's closed form and tolerance are checked inside the tool; the
   * test checks that the file says so and that the quantities are real
   * comparisons (closed form, computed, error within tolerance).
   */
  nlohmann::json
  verify(const std::string &name)
  {
    const std::string output = fresh_output_folder("verify_" + name);
    const auto        result =
      run_floorblock("verify " + name + " --output " + shell_quoted(output));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    nlohmann::json json = read_json(output + "/verify.json");
    std::filesystem::remove_all(output);
    return json;
  }

  void
  expect_passed(const nlohmann::json           &json,
                const std::string              &name,
                const std::vector<std::string> &quantities)
  {
    EXPECT_EQ(json["case"].get<std::string>(), name);
    EXPECT_TRUE(json["passed"].get<bool>());
    for (const std::string &quantity : quantities)
      {
        ASSERT_TRUE(json["quantities"].contains(quantity)) << quantity;
        const auto &q = json["quantities"][quantity];
        for (const char *key :
             {"computed", "closed_form", "relative_error", "tolerance"})
          EXPECT_TRUE(q.contains(key)) << quantity << "." << key;
        EXPECT_LE(q["relative_error"].get<double>(),
                  q["tolerance"].get<double>())
          << quantity;
        EXPECT_TRUE(q["passed"].get<bool>()) << quantity;
      }
  }
} // namespace

// The tool shall verify the contact patch test: uniform pressure to 1e-8.
TEST(VerifyCommand, PatchTransmitsUniformPressure)
{
  const auto json = verify("patch");
  expect_passed(json,
                "patch",
                {"joint_normal_force",
                 "lowest_normal_traction",
                 "highest_normal_traction",
                 "joint_shear_force_over_normal"});
  EXPECT_EQ(json["quantities"]["joint_normal_force"]["tolerance"].get<double>(),
            1e-8);
}

// The tool shall verify the incline: stuck below, slipping above
// tan(alpha) = mu, and the stuck joint shear W sin(alpha).
TEST(VerifyCommand, InclineSlipsOnlyAboveTheFrictionAngle)
{
  const auto json = verify("incline");
  expect_passed(json,
                "incline",
                {"slips_below_threshold",
                 "slips_above_threshold",
                 "joint_shear_force",
                 "joint_normal_force"});
  EXPECT_EQ(
    json["quantities"]["slips_above_threshold"]["computed"].get<double>(), 1.);
  EXPECT_EQ(
    json["quantities"]["slips_below_threshold"]["computed"].get<double>(), 0.);
}

// The tool shall verify two blocks: joint force = applied lateral load.
TEST(VerifyCommand, TwoBlocksJointForceEqualsLateralLoad)
{
  const auto json = verify("two-blocks");
  expect_passed(json, "two-blocks", {"joint_normal_force"});
  // Closed form: 4e5 Pa on the upper 0.5 m of the block.
  EXPECT_DOUBLE_EQ(
    json["quantities"]["joint_normal_force"]["closed_form"].get<double>(), 2e5);
}

// Issue 15: the tool shall fit the corner exponent of a square block
// pressed on a similar base and match the eigen-solver within 0.03, stuck
// (Williams' 270 deg corner, 0.5445) and frictionless (0.7740), stating the
// fit range.
TEST(VerifyCommand, PunchCornerExponentsMatchTheEigenSolver)
{
  const auto json = verify("punch");
  expect_passed(json,
                "punch",
                {"stuck_corner_exponent", "frictionless_corner_exponent"});
  const auto &q = json["quantities"];
  EXPECT_NEAR(q["stuck_corner_exponent"]["closed_form"].get<double>(),
              0.544484,
              1e-6);
  EXPECT_NEAR(q["frictionless_corner_exponent"]["closed_form"].get<double>(),
              0.774013,
              1e-6);
  for (const char *state : {"stuck", "frictionless"})
    {
      const std::string prefix(state);
      EXPECT_LT(q[prefix + "_fit_from_m"].get<double>(),
                q[prefix + "_fit_to_m"].get<double>());
      EXPECT_GE(q[prefix + "_fit_points"].get<int>(), 10);
    }
}

// The tool shall refuse an unknown case and name the available ones.
TEST(VerifyCommand, UnknownCaseIsRefused)
{
  const auto result = run_floorblock("verify nonsense");
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.output.find("two-blocks"), std::string::npos)
    << result.output;
}
