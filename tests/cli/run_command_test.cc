#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "estimate_checks.h"
#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{

  /// Runs the 3-block scene once for all tests of this file.
  const std::string &
  three_block_run()
  {
    static const std::string output = [] {
      const std::string folder = fresh_output_folder("run_three_blocks");
      const auto        result =
        run_floorblock("run tests/scenarios/three_blocks.prm --output " +
                       shell_quoted(folder));
      EXPECT_EQ(result.exit_code, 0) << result.output;
      return folder;
    }();
    return output;
  }

  // E, b, L, H of the scene as the comparison records carry them.
  double
  corner_sigma_max(const double q_over_b,
                   const double lift,
                   const double e,
                   const double b,
                   const double l)
  {
    // Eq. 6.53 recomputed here independently of the library.
    return std::sqrt(2. * lift * e * q_over_b / (b * l * l));
  }
} // namespace

// The tool shall name, for every figure, the joint that carries the most
// (Q among the vertical joints, the stresses among all joints), where, and
// the face joint's value beside it: in summary.json, report.md, the
// terminal and a plot along the lift. On the 3-block scene a bedding joint
// carries the largest peak stress.
TEST(RunCommand, NamesTheGoverningJointOfEveryFigure)
{
  const std::string folder  = three_block_run();
  const json        summary = read_json(folder + "/summary.json");
  ASSERT_TRUE(summary.contains("governing_joints"));
  const json                              &joints  = summary["fem"]["joints"];
  const std::map<std::string, std::string> figures = {
    {"Q_N_per_m", "normal_force_N_per_m"},
    {"sigma_max_Pa", "sigma_max_Pa"},
    {"sigma_max_averaged_Pa", "sigma_max_averaged_Pa"},
    {"sigma_mean_Pa", "sigma_mean_Pa"}};
  ASSERT_EQ(summary["governing_joints"].size(), figures.size());
  bool bedding_governs = false;
  for (const json &entry : summary["governing_joints"])
    {
      const std::string figure  = entry["figure"];
      const std::string key     = figures.at(figure);
      double            largest = 0., face = 0.;
      for (const json &joint : joints)
        {
          const std::string name = joint["name"];
          if (name == "vertical 3")
            face = joint[key].get<double>();
          if (figure != "Q_N_per_m" || joint["kind"] == "vertical")
            largest = std::max(largest, joint[key].get<double>());
        }
      EXPECT_NEAR(entry["value"].get<double>(), largest, 1e-9 * largest)
        << figure;
      EXPECT_NEAR(entry["face_joint_value"].get<double>(), face, 1e-9 * face)
        << figure;
      bedding_governs = bedding_governs ||
                        entry["joint"].get<std::string>().find("bedding") == 0;
    }
  EXPECT_TRUE(bedding_governs) << summary["governing_joints"];

  std::ifstream     file(folder + "/report.md");
  const std::string report((std::istreambuf_iterator<char>(file)),
                           std::istreambuf_iterator<char>());
  EXPECT_NE(report.find("## Governing joints"), std::string::npos);
  EXPECT_NE(report.find("| pointwise peak normal stress | bedding"),
            std::string::npos)
    << report;
  EXPECT_TRUE(std::filesystem::exists(folder + "/stress_vs_lift.png"));
}

// The tool shall name the loaded blocks in report.md in both numberings:
// 2nd and 3rd from the face are blocks 2 and 1 of three.
TEST(RunCommand, ReportNamesTheLoadedBlocksInItsNumbering)
{
  const std::string report = read_text(three_block_run() + "/report.md");
  EXPECT_NE(report.find("on blocks 2,3 from the face (blocks 1, 2 in this "
                        "report's numbering)"),
            std::string::npos)
    << report;
}

// The tool shall write every result file of a run, summary.json last.
TEST(RunCommand, WritesEveryFile)
{
  const std::string &output = three_block_run();
  for (const char *name : {"original.prm",
                           "parameters.prm",
                           "analytic.json",
                           "analytic.csv",
                           "fem.json",
                           "joints.csv",
                           "summary.json",
                           "report.md",
                           "q_per_joint.png",
                           "face_joint_vs_lift.png",
                           "face_joint_traction.png",
                           "stress_vs_lift.png",
                           "mesh.msh"})
    EXPECT_TRUE(std::filesystem::exists(output + "/" + name)) << name;
  const auto summary_time =
    std::filesystem::last_write_time(output + "/summary.json");
  for (const char *name : {"fem.json", "report.md", "q_per_joint.png"})
    EXPECT_LE(std::filesystem::last_write_time(output + "/" + name),
              summary_time)
      << name << " was written after summary.json";
}

// The tool shall document its results under the keys other scripts rely on.
TEST(RunCommand, SummaryHasDocumentedKeys)
{
  const json summary = read_json(three_block_run() + "/summary.json");
  for (const char *key : {"status", "analytic", "fem", "comparison"})
    ASSERT_TRUE(summary.contains(key)) << key;
  EXPECT_EQ(summary["status"], "converged");
  const auto &joints = summary["fem"]["joints"];
  ASSERT_EQ(joints.size(), 6u); // 3 vertical + 3 bedding joints
  for (const auto &joint : joints)
    for (const char *key : {"name",
                            "kind",
                            "blocks",
                            "normal_force_N_per_m",
                            "shear_force_N_per_m",
                            "contact_length_m",
                            "contact_area_m2",
                            "sigma_max_Pa",
                            "sigma_max_averaged_Pa",
                            "state"})
      EXPECT_TRUE(joint.contains(key)) << key;
  const auto &final = summary["comparison"]["final"];
  ASSERT_EQ(final.size(), 3u);
  for (const char *key : {"Q_contact_N",
                          "y_m",
                          "E_Pa",
                          "b_m",
                          "L_m",
                          "A_6_51_m2",
                          "sigma_max_6_53_Pa",
                          "A_fem_m2"})
    EXPECT_TRUE(final.back()["contact"].contains(key)) << key;
  EXPECT_FALSE(summary["comparison"]["lift_history"].empty());
}

// Every FEM figure at the face joint carries its error estimate (or says
// why there is none) and the time of the solve, next to its value.
TEST(RunCommand, FaceJointFiguresCarryErrorAndTime)
{
  const std::string &output  = three_block_run();
  const json         fem     = read_json(output + "/fem.json");
  const json         summary = read_json(output + "/summary.json");
  json               face;
  for (const auto &joint : fem["joints"])
    if (joint["name"] == "vertical 3")
      face = joint;
  const auto &figures = summary["face_joint_figures"];
  ASSERT_EQ(figures.size(), 4u);
  for (const auto &figure : figures)
    {
      const std::string field = figure["field"].get<std::string>();
      EXPECT_DOUBLE_EQ(figure["value"].get<double>(),
                       face[field].get<double>());
      EXPECT_GT(figure["wall_time_s"].get<double>(), 0.);
      // The scene asks for no estimate: the error is null and says why.
      EXPECT_TRUE(figure["relative_error"].is_null());
      EXPECT_NE(figure["error_method"].get<std::string>().find("none"),
                std::string::npos);
    }
}

// The tool shall print error estimates that bracket the converged value.
// Reference: the face joint on level 3 of the nested uniform ladder
// (311680 DoFs, `floorblock converge params/default.prm --mode uniform
// --levels 4 --set "Solver/Max direct DoFs=1000000"`, 2026-11-25; level 3
// differs from level 2 by 0.08 % in contact length, 0.11 % in the peak,
// 0.9 % in the averaged peak, 0.009 % in Q).
TEST(RunCommand, DefaultSceneErrorEstimatesBracketTheFinestLevel)
{
  const std::string folder = fresh_output_folder("run_default_bracket");
  const auto        result =
    run_floorblock("run params/default.prm --output " + shell_quoted(folder));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const json  summary = read_json(folder + "/summary.json");
  const json &face    = summary["fem_error_estimate"]["joints"]["vertical 6"];
  expect_estimates_bracket(face,
                           {{"normal_force_N_per_m", 2.728901898e+06},
                            {"contact_length_m", 3.477503582e-01},
                            {"sigma_max_Pa", 1.587684071e+07},
                            {"sigma_max_averaged_Pa", 1.454455876e+07}});
  // The floor's safety factors at the face corner against the default
  // scene solved with Mesh/Global refinements = 3 (979,376 DoFs; `solve
  // params/default.prm --set "Mesh/Global refinements=3" --set
  // "Solver/Max direct DoFs=2000000"`, fem.json floor_safety.corners;
  // refinements 2 give 0.7473, 0.9230, 0.9790).
  expect_estimates_bracket(
    summary["fem_error_estimate"]["corners"]["face block at vertical 6"],
    {{"safety_factor_point", 7.467278539e-01},
     {"safety_factor_line", 9.240912483e-01},
     {"safety_factor_area", 9.757133924e-01}});
  // Issue 14: the default mesh (sized from the scene, Mesh/Cells per
  // contact length) gives the face contact length within 1 % of the
  // converged value. Measured 347.07 mm: 0.2 % short of the reference
  // above; the same-mesh nested ladder gives 347.65 mm on 363k DoFs.
  const double contact = face["contact_length_m"]["value"].get<double>();
  EXPECT_LE(std::abs(contact - 3.477503582e-01), 0.01 * 3.477503582e-01)
    << "face contact length " << contact;
}

// The tool shall compare numbers that anyone can recompute from fem.json
// and analytic.json (to 1e-12 relative: the same doubles, re-derived).
TEST(RunCommand, ComparisonEqualsRecomputedValues)
{
  const std::string &output   = three_block_run();
  const json         fem      = read_json(output + "/fem.json");
  const json         analytic = read_json(output + "/analytic.json");
  const json         summary  = read_json(output + "/summary.json");
  const double       b        = fem["b_m"].get<double>();

  for (const auto &record : summary["comparison"]["final"])
    {
      const unsigned int joint = record["joint"].get<unsigned int>();
      const std::string  name  = "vertical " + std::to_string(joint);
      json               fem_joint;
      for (const auto &candidate : fem["joints"])
        if (candidate["name"] == name)
          fem_joint = candidate;
      ASSERT_FALSE(fem_joint.is_null()) << name;

      const double q_fem = fem_joint["normal_force_N_per_m"].get<double>();
      EXPECT_DOUBLE_EQ(record["Q_fem_N_per_m"].get<double>(), q_fem);
      for (const auto &[mechanism, value] : record["Q_closed_form"].items())
        {
          const auto &list = analytic["cases"][mechanism]["Q_N_per_m"];
          if (list.empty())
            {
              EXPECT_TRUE(value["Q_N_per_m"].is_null()) << mechanism;
              continue;
            }
          const double q_closed = list[joint - 1].get<double>();
          EXPECT_DOUBLE_EQ(value["Q_N_per_m"].get<double>(), q_closed);
          EXPECT_NEAR(value["relative_difference"].get<double>(),
                      (q_fem - q_closed) / std::abs(q_closed),
                      1e-12);
        }

      const auto &contact = record["contact"];
      EXPECT_DOUBLE_EQ(contact["Q_contact_N"].get<double>(),
                       std::max(q_fem, 0.) * b);
      EXPECT_NEAR(contact["A_fem_m2"].get<double>(),
                  fem_joint["contact_length_m"].get<double>() * b,
                  1e-15);
      if (contact["sigma_max_6_53_Pa"].is_number())
        EXPECT_NEAR(contact["sigma_max_6_53_Pa"].get<double>(),
                    corner_sigma_max(contact["Q_contact_N"].get<double>(),
                                     contact["y_m"].get<double>(),
                                     contact["E_Pa"].get<double>(),
                                     contact["b_m"].get<double>(),
                                     contact["L_m"].get<double>()),
                    1e-9 * contact["sigma_max_6_53_Pa"].get<double>());
    }
}

// Issue 14, accuracy as the input. The 3-block scene (coarse: 1066 DoFs,
// sharp corners) with the default 1 % target and at most 3 adaptive levels.
// Level 0's check (its mesh with every cell halved) gives 2.5 % for level 0
// and 1.2 % for the check itself (Roache's GCI of the finer grid, half the
// coarse one's); level 1 differs from level 0 by 6.8 % (indicator) and is
// not checked; level 2 differs from level 1 by 0.5 % x 6, but its check
// gives 3.8 % and 1.9 % (two adaptive levels can agree while both are
// off: an indicator, not an estimate); level 3 is not checked and the
// levels run out. The tool shall say so, report the solve of the last
// check with the smaller estimate -- level 2's check, which brackets the
// converged value -- and put that solve's files in the result folder.
TEST(RunCommand, AccuracyLoopThatRunsOutReportsTheLastCheck)
{
  const std::string folder = fresh_output_folder("run_accuracy_levels");
  const auto        result = run_floorblock(
    "run tests/scenarios/three_blocks.prm --output " + shell_quoted(folder) +
    " --set 'Solver/Error estimate=refined solve'"
           " --set 'Solver/FE degree=1'"
           " --set 'Mesh/Maximum refinement levels=3'");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("NOT met"), std::string::npos) << result.output;
  const json  summary  = read_json(folder + "/summary.json");
  const json &estimate = summary["fem_error_estimate"];
  const json &target   = estimate["target"];
  EXPECT_FALSE(target["met"].get<bool>());
  EXPECT_NE(target["stop_reason"].get<std::string>().find(
              "Maximum refinement levels = 3"),
            std::string::npos);
  ASSERT_EQ(target["levels"].size(), 4u);
  const unsigned int reported = target["reported_level"].get<unsigned int>();
  EXPECT_EQ(reported, 2u);
  EXPECT_EQ(target["reported_solve"].get<std::string>(), "refined");
  EXPECT_EQ(estimate["reported_solve"].get<std::string>(), "refined");
  for (unsigned int level = 1; level < 4; ++level)
    EXPECT_GT(target["levels"][level]["n_dofs"].get<unsigned int>(),
              target["levels"][level - 1]["n_dofs"].get<unsigned int>());
  // Checked levels have both estimates; the others only an indicator.
  for (const unsigned int level : {0u, 2u})
    {
      const json  &record = target["levels"][level];
      const double coarse = record["worst_target_relative_error"].get<double>();
      const double check =
        record["halved_worst_target_relative_error"].get<double>();
      EXPECT_GT(coarse, 0.01) << level;
      EXPECT_GT(check, 0.01) << level;
      EXPECT_LT(check, coarse) << level; // 3 against 6 times the difference
    }
  for (const unsigned int level : {1u, 3u})
    {
      EXPECT_TRUE(
        target["levels"][level]["worst_target_relative_error"].is_null());
      EXPECT_TRUE(target["levels"][level]["halved_worst_target_relative_error"]
                    .is_null());
    }
  EXPECT_LE(target["levels"][2]["difference_indicator"].get<double>(), 0.01);

  // The reported solve's files are the folder's, and its figures are the
  // estimate's values.
  const json fem = read_json(folder + "/fem.json");
  EXPECT_EQ(fem["n_dofs"].get<unsigned int>(),
            target["levels"][reported]["halved_n_dofs"].get<unsigned int>());
  EXPECT_EQ(read_json(folder + "/refined/level_2_halved/fem.json")["joints"],
            fem["joints"]);
  for (const json &joint : fem["joints"])
    if (joint["name"] == "vertical 3")
      EXPECT_EQ(joint["contact_length_m"].get<double>(),
                estimate["joints"]["vertical 3"]["contact_length_m"]["value"]
                  .get<double>());

  expect_estimates_bracket(estimate["joints"]["vertical 3"],
                           three_blocks_converged_face);
}
