// How a scene's inputs that depend on each other reach the results: values
// derived from others, echoed where the user looks, and contradictions
// refused or said out loud.

#include <gtest/gtest.h>

#include <filesystem>

#include "process.h"

using namespace FloorBlockTest;

namespace
{
  /// Eight 1.2 m blocks on y = x^2/100: the bed rises (9.6 m)^2/100 m =
  /// 0.9216 m from the face to the free end.
  const std::string steep_bed_of_eight_blocks =
    " --set 'Geometry/Number of blocks=8' --set 'Geometry/Block width=1.2'"
    " --set 'Bedding/Curvature=100'";
} // namespace

// The tool shall lift the FEM's floor by the bedding's rise when Floor lift
// is auto, and echo the derived value in parameters.prm.
TEST(FloorLift, AutoTakesTheBeddingsRiseAndEchoesIt)
{
  const std::string folder = fresh_output_folder("floor_lift_auto");
  const auto        result =
    run_floorblock("analytic params/default.prm" + steep_bed_of_eight_blocks +
                   " --output " + shell_quoted(folder));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const std::string parameters = read_text(folder + "/parameters.prm");
  EXPECT_NE(parameters.find("set Floor lift"), std::string::npos);
  EXPECT_NE(parameters.find("= auto # auto: (nL)^2/k"), std::string::npos)
    << parameters;
  EXPECT_NE(parameters.find("= 0.9216 m"), std::string::npos) << parameters;
  std::filesystem::remove_all(folder);
}

// The tool shall refuse a floor lift that contradicts the bedding, naming
// both values and the ways out, for every command that reads the scene.
TEST(FloorLift, ContradictingLiftIsRefusedByEveryCommand)
{
  for (const std::string command : {"analytic", "solve", "run"})
    {
      const std::string folder = fresh_output_folder("floor_lift_refused");
      const auto        result = run_floorblock(
        command + " params/default.prm" + steep_bed_of_eight_blocks +
        " --set 'Loading/Floor lift=0.09' --output " + shell_quoted(folder));
      EXPECT_EQ(result.exit_code, 2) << command << ": " << result.output;
      for (const char *phrase : {"Loading/Floor lift",
                                 "0.09",
                                 "0.9216 m",
                                 "Floor lift = auto",
                                 "may differ"})
        EXPECT_NE(result.output.find(phrase), std::string::npos)
          << command << " does not mention '" << phrase << "':\n"
          << result.output;
      EXPECT_FALSE(std::filesystem::exists(folder)) << command;
    }
}

// The tool shall accept a lift within 1 % of the bedding's rise as the
// bedding's.
TEST(FloorLift, LiftWithinOnePercentOfTheBeddingIsAccepted)
{
  const std::string folder = fresh_output_folder("floor_lift_close");
  const auto        result = run_floorblock(
    "analytic params/default.prm" + steep_bed_of_eight_blocks +
    " --set 'Loading/Floor lift=0.92' --output " + shell_quoted(folder));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output.find("warning"), std::string::npos) << result.output;
  std::filesystem::remove_all(folder);
}

// The tool shall say in the terminal and in report.md when the FEM lifts
// another floor than the closed forms stand the blocks on.
TEST(FloorLift, DeliberatelyDifferentLiftIsReportedOutLoud)
{
  const std::string folder = fresh_output_folder("floor_lift_differs");
  const auto        result = run_floorblock(
    "run tests/scenarios/hard_large_lift.prm --set 'Solver/Error "
           "estimate=none' --output " +
    shell_quoted(folder));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const std::string warning = "Loading/Floor lift = 0.1 m differs from the "
                              "bedding's (nL)^2/k";
  EXPECT_NE(result.output.find("warning: " + warning), std::string::npos)
    << result.output;
  const std::string report = read_text(folder + "/report.md");
  EXPECT_NE(report.find("**Warning:** " + warning), std::string::npos)
    << report;
  std::filesystem::remove_all(folder);
}

// The tool shall warn where the closed forms define no FEM lift: a flat
// bed translated along itself under an inclined bedding is a motion they
// do not describe. A level bed translated along itself (S6) keeps their
// bed, and the motion only drives the slip they describe: no warning.
TEST(FloorLift, MotionTheClosedFormsDoNotDescribeIsWarnedAbout)
{
  const std::string folder   = fresh_output_folder("floor_lift_s6");
  const std::string moves    = "warning: Loading/Floor lift = 0.01 m moves "
                               "the FEM's base";
  const auto        inclined = run_floorblock(
    "analytic params/s6.prm --set Bedding/Inclination=5 --output " +
    shell_quoted(folder));
  EXPECT_EQ(inclined.exit_code, 0) << inclined.output;
  EXPECT_NE(inclined.output.find(moves), std::string::npos) << inclined.output;
  std::filesystem::remove_all(folder);

  const auto level =
    run_floorblock("analytic params/s6.prm --output " + shell_quoted(folder));
  EXPECT_EQ(level.exit_code, 0) << level.output;
  EXPECT_EQ(level.output.find(moves), std::string::npos) << level.output;
  std::filesystem::remove_all(folder);
}

// The tool shall take the rock's moduli as a site report gives them,
// Young's modulus and Poisson's ratio, and echo the bulk and shear moduli
// it derives from them.
TEST(Moduli, YoungsModulusAndPoissonsRatioGiveBulkAndShear)
{
  const std::string folder = fresh_output_folder("moduli_e_nu");
  const auto        result = run_floorblock(
    "analytic params/default.prm --set 'Material/Bulk modulus=auto' "
           "--set 'Material/Shear modulus=auto' "
           "--set \"Material/Young's modulus=12e9\" "
           "--set \"Material/Poisson's ratio=0.25\" --output " +
    shell_quoted(folder));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const std::string parameters = read_text(folder + "/parameters.prm");
  // K = E / (3 (1 - 2 nu)) = 8 GPa, G = E / (2 (1 + nu)) = 4.8 GPa.
  EXPECT_NE(parameters.find("= auto # derived from E and nu: 8e+09 Pa"),
            std::string::npos)
    << parameters;
  EXPECT_NE(parameters.find("= auto # derived from E and nu: 4.8e+09 Pa"),
            std::string::npos)
    << parameters;
  std::filesystem::remove_all(folder);
}

// The tool shall say which blocks carry the support in the numbering of
// its output, where block 1 is at the free end.
TEST(LoadedBlocks, NamedInTheOutputsNumbering)
{
  const std::string folder = fresh_output_folder("loaded_blocks");
  const auto        result = run_floorblock(
    "analytic params/default.prm --set 'Geometry/Number of blocks=8' "
           "--set 'Loading/Loaded blocks from face=1,2,3' --output " +
    shell_quoted(folder));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("Support load on blocks 6, 7, 8 (1 = free end"),
            std::string::npos)
    << result.output;
  std::filesystem::remove_all(folder);
}

// The tool shall run the FEM only on the grid points the user chose:
// a figure, its curvatures and a support load range.
TEST(SweepFem, RunsTheChosenFigureCurvatureAndLoads)
{
  const std::string folder = fresh_output_folder("sweep_chosen");
  const auto        result = run_floorblock(
    "sweep tests/scenarios/three_blocks.prm --fem --figure fig6_10_11 "
           "--curvatures 50 --loads 850,900 --limit 1 --output " +
    shell_quoted(folder));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  // k = 50 m and 900 t: the six bedding friction angles, one run.
  EXPECT_NE(result.output.find("1 of 6 chosen FEM cases finished"),
            std::string::npos)
    << result.output;
  std::filesystem::remove_all(folder);
}
