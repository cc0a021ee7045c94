// Closed forms in the scene's own frame: a verdict only where the FEM
// solves the scene the closed forms describe, and the closed forms' inputs
// named beside it.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  const std::vector<std::string> frame_mechanisms =
    {"no_rotation", "rotation_no_vertical_slip", "rotation_vertical_slip"};

  // A flat mesh raised straight up under a planar bedding inclined 5 deg:
  // the FEM's blocks stand on a level bed, the closed forms' on the
  // inclined one. The rigid-block model keeps the test fast; it goes
  // through the same comparison as the elastic FEM.
  TEST(SceneFrame, AnotherSceneGetsNoPercentageVerdict)
  {
    const std::string folder = fresh_output_folder("other_scene");
    const auto        run    = run_floorblock(
      "run params/default.prm --set \"Bedding/Shape=planar\" "
                "--set \"Bedding/Inclination=5\" --set \"Loading/Uplift mode=vertical\" "
                "--set \"Loading/Floor lift=0.05\" --set \"Model/Blocks=rigid\" "
                "--output " +
      shell_quoted(folder));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("no verdict on the lateral force Q"),
              std::string::npos)
      << run.output;
    EXPECT_NE(run.output.find("the closed forms describe another scene"),
              std::string::npos)
      << run.output;
    for (const char *word : {"overestimates the lateral force",
                             "underestimates the lateral force",
                             "matches the FEM lateral force"})
      EXPECT_EQ(run.output.find(word), std::string::npos) << word;

    const json  summary    = read_json(folder + "/summary.json");
    const json &comparison = summary["comparison"];
    EXPECT_EQ(comparison["closed_form_inputs"]["scene_differences"].size(), 1u);
    for (const json &joint : comparison["final"])
      for (const std::string &mechanism : frame_mechanisms)
        {
          const json &force = joint["Q_closed_form"][mechanism];
          EXPECT_TRUE(force["relative_difference"].is_null()) << mechanism;
          EXPECT_TRUE(force["difference_N_per_m"].is_null()) << mechanism;
          if (!force["Q_N_per_m"].is_null())
            EXPECT_EQ(force["status"], "other_scene") << mechanism;
        }
  }

  // S6 turns its frame by 10 deg: the closed forms take alpha = -10 deg
  // on every block (a level bed falling away from the face), the same
  // scene as the FEM's, so they give their verdicts.
  TEST(SceneFrame, FrameDipEntersAlphaAndKeepsTheVerdicts)
  {
    const std::string folder = fresh_output_folder("s6_frame");
    const auto        run =
      run_floorblock("run params/s6.prm --output " + shell_quoted(folder));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const json  summary = read_json(folder + "/summary.json");
    const json &inputs  = summary["comparison"]["closed_form_inputs"];
    EXPECT_TRUE(inputs["scene_differences"].empty());
    ASSERT_EQ(inputs["alpha_rad"].size(), 6u);
    for (const json &alpha : inputs["alpha_rad"])
      EXPECT_NEAR(alpha.get<double>(), -10. * M_PI / 180., 1e-15);
    const json &face = summary["comparison"]["final"].back();
    EXPECT_TRUE(
      face["Q_closed_form"]["no_rotation"]["relative_difference"].is_number());
    EXPECT_NE(run.output.find("alpha = -10 deg against the true horizontal"),
              std::string::npos)
      << run.output;
  }

  // A scene of S6's family: a 5 deg frame dip, vertical joints of 10 deg
  // friction, no support load. Where the FEM's chain slips on every joint
  // (joints 1..k), the slip mechanism whose geometry is the scene's (blocks
  // flush on the bed: rotation_vertical_slip) gives the FEM's Q to 1e-3;
  // the face verdict says which mechanism assumes the FEM's joint states.
  TEST(SceneFrame, SlipMechanismGivesTheFemsQWhereTheFemSlips)
  {
    const std::string folder = fresh_output_folder("s6_family");
    const auto        run =
      run_floorblock("run params/s6.prm --set \"Bedding/Frame dip=5\" "
                     "--set \"Joints/Vertical friction angle=10\" "
                     "--set \"Loading/Support load=0\" --output " +
                     shell_quoted(folder));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const json   summary  = read_json(folder + "/summary.json");
    const json  &states   = summary["comparison"]["fem_joint_states"];
    unsigned int slipping = 0;
    for (const json &holds : states["slip_chain_holds"])
      if (holds.get<bool>())
        ++slipping;
      else
        break;
    ASSERT_GE(slipping, 3u) << states.dump();
    for (const json &joint : summary["comparison"]["final"])
      if (joint["joint"].get<unsigned int>() <= slipping)
        {
          const json &force = joint["Q_closed_form"]["rotation_vertical_slip"];
          ASSERT_TRUE(force["relative_difference"].is_number());
          EXPECT_LT(std::abs(force["relative_difference"].get<double>()), 1e-3)
            << joint.dump();
        }
    EXPECT_NE(run.output.find("the FEM's joints: "), std::string::npos)
      << run.output;
    EXPECT_NE(run.output.find("joints 1 to " + std::to_string(slipping) +
                              ": the FEM's blocks slip on every joint"),
              std::string::npos)
      << run.output;
  }
} // namespace
