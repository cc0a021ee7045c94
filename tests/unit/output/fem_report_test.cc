// The FEM report's text and numbers: stage and joint names, joints.csv
// (header, one row per joint per increment, 10 significant digits),
// fem.json's joint record and force-balance summary, and the sentences
// printed for unloaded increments.
#include <compare/load_check.h>
#include <contact/results.h>
#include <output/fem_report.h>
#include <output/numbering_note.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace FloorBlock;
  using nlohmann::json;

  constexpr double support_width = 1.5; // b (m)

  Output::FemReportContext
  context()
  {
    return {2, support_width, "converged", "all stages reached", 16e9};
  }

  Contact::JointReport
  joint(const std::string &name, const double normal_force,
        const double closed_length, const unsigned int n_stick,
        const unsigned int n_slip, const unsigned int n_open)
  {
    Contact::JointReport report;
    report.name                        = name;
    report.normal_force                = normal_force;
    report.shear_force                 = -0.25 * normal_force;
    report.closed_length               = closed_length;
    report.peak_normal_stress          = 3.5e6;
    report.averaged_peak_normal_stress = 2.75e6;
    report.mean_normal_stress =
      closed_length > 0. ? normal_force / closed_length : 0.;
    report.counts = {n_stick, n_slip, n_open};
    return report;
  }

  /** Two loaded increments of a 2-block scene; 1 mm translations. */
  Contact::SolveResult
  two_increments()
  {
    Contact::SolveResult result;
    for (const auto &[stage, factor] :
         {std::pair{Contact::LoadStage::gravity, 1.},
          std::pair{Contact::LoadStage::uplift, 0.5}})
      {
        Contact::IncrementResult increment;
        increment.stage                          = stage;
        increment.stage_factor                   = factor;
        increment.balance.applied_load[1]        = -90e3;
        increment.balance.support_reaction[1]    = 90e3;
        increment.balance.support_reaction[0]    = 9e-9; // the imbalance
        increment.balance.relative_imbalance     = 5e-14;
        increment.joints = {joint("vertical 1", 123456.789, 0.4, 3, 1, 2),
                            joint("vertical 2", 98765.4321, 0., 0, 0, 6),
                            joint("bedding 1", 45e3, 1., 0, 5, 0)};
        increment.motions[1].translation[0] = 1e-3;
        result.increments.push_back(increment);
      }
    return result;
  }

  std::vector<std::string>
  split(const std::string &text, const char separator)
  {
    std::vector<std::string> parts;
    std::istringstream       stream(text);
    for (std::string part; std::getline(stream, part, separator);)
      parts.push_back(part);
    return parts;
  }

  TEST(FemReport, StageNames)
  {
    EXPECT_EQ(Output::stage_name(Contact::LoadStage::gravity), "gravity");
    EXPECT_EQ(Output::stage_name(Contact::LoadStage::support_pressure),
              "support_load");
    EXPECT_EQ(Output::stage_name(Contact::LoadStage::uplift), "uplift");
  }

  // Chapter numbering: vertical j lies between j and j+1, vertical n
  // against the face block, bedding i under block i.
  TEST(FemReport, JointBodiesInTheChaptersNumbering)
  {
    EXPECT_EQ(Output::joint_bodies("vertical", 2, 6), (json{2, 3}));
    EXPECT_EQ(Output::joint_bodies("vertical", 6, 6), (json{6, "face"}));
    EXPECT_EQ(Output::joint_bodies("bedding", 4, 6), (json{4, "base"}));
  }

  // Two comment lines (the numbering note and b), the column names, then
  // one row per joint per increment with the increment counted from 1.
  TEST(FemReport, JointsCsvHeaderAndRows)
  {
    const std::string csv = Output::joints_csv(two_increments(), context());
    const auto        lines = split(csv, '\n');
    ASSERT_EQ(lines.size(), 3u + 2u * 3u);
    EXPECT_EQ(lines[0], std::string("# ") + Output::numbering_note);
    EXPECT_EQ(lines[1], "# Forces per metre of face; areas over b = 1.5 m.");
    const auto columns = split(lines[2], ',');
    ASSERT_EQ(columns.size(), 15u);
    EXPECT_EQ(columns.front(), "increment");
    EXPECT_EQ(columns[5], "normal_force_N_per_m");
    EXPECT_EQ(columns[8], "contact_area_m2");
    EXPECT_EQ(columns.back(), "n_open");

    // Increment 2 (uplift at half its load), vertical 1: exact text for the
    // words and counts, 10 significant digits for the numbers.
    const auto row = split(lines[6], ',');
    ASSERT_EQ(row.size(), 15u);
    EXPECT_EQ(row[0], "2");
    EXPECT_EQ(row[1], "uplift");
    EXPECT_EQ(row[2], "0.500000");
    EXPECT_EQ(row[3], "vertical 1");
    EXPECT_EQ(row[4], "vertical");
    EXPECT_EQ(row[5], "1.234567890e+05");
    EXPECT_EQ(row[6], "-3.086419725e+04");
    // Contact area = length x b = 0.4 x 1.5 m^2, read back to the 10
    // significant digits written (relative 5e-10).
    EXPECT_NEAR(std::stod(row[8]), 0.6, 5e-10 * 0.6);
    EXPECT_NEAR(std::stod(row[11]), 123456.789 / 0.4, 5e-10 * 123456.789 / 0.4);
    EXPECT_EQ(row[12], "3");
    EXPECT_EQ(row[13], "1");
    EXPECT_EQ(row[14], "2");
    EXPECT_EQ(split(lines[8], ',')[4], "bedding");
  }

  // fem.json reports the last increment's joints with forces over b and
  // the contact state in words.
  TEST(FemReport, JointJsonOverTheSupportWidth)
  {
    const json fem = Output::fem_json(two_increments(), context());
    EXPECT_EQ(fem["n_increments"], 2);
    EXPECT_EQ(fem["b_m"], support_width);
    ASSERT_EQ(fem["joints"].size(), 3u);
    const json &first = fem["joints"][0];
    EXPECT_EQ(first["blocks"], (json{1, 2}));
    EXPECT_NEAR(first["normal_force_N_over_b"].get<double>(),
                123456.789 * 1.5, 1e-12 * 123456.789 * 1.5);
    EXPECT_NEAR(first["contact_area_m2"].get<double>(), 0.6, 1e-12);
    EXPECT_EQ(first["state"], "stick-slip");
    EXPECT_EQ(fem["joints"][1]["blocks"], (json{2, "face"}));
    EXPECT_EQ(fem["joints"][1]["state"], "open");
    EXPECT_EQ(fem["joints"][2]["blocks"], (json{1, "base"}));
    EXPECT_EQ(fem["joints"][2]["state"], "slip");
  }

  // Loaded increments: the worst relative error and |applied + reaction|
  // = 9e-9 N/m, both with 2 significant digits.
  TEST(FemReport, ForceBalanceTextOfALoadedRun)
  {
    const json fem = Output::fem_json(two_increments(), context());
    EXPECT_EQ(fem["force_balance_status"], "ok");
    EXPECT_NEAR(fem["force_balance_absolute_error_N_per_m"].get<double>(), 9e-9,
                1e-12 * 9e-9);
    EXPECT_EQ(Output::force_balance_text(fem),
              "force balance error 5.0e-14 (9.0e-09 N/m)");
  }

  TEST(FemReport, ForceBalanceTextWithoutLoadOrIncrements)
  {
    Contact::SolveResult unloaded;
    unloaded.increments.resize(1);
    unloaded.increments[0].balance.applied_load[1]     = 1e-6;
    unloaded.increments[0].balance.relative_imbalance = 0.5;
    unloaded.increments[0].motions[1].translation[1]   = 1e-2;
    const json fem = Output::fem_json(unloaded, context());
    EXPECT_EQ(fem["force_balance_status"], "no load");
    EXPECT_EQ(fem["force_balance_relative_error"], 0.);
    EXPECT_EQ(Output::force_balance_text(fem),
              "no load (force balance 1.0e-06 N/m, round-off)");

    const json none = Output::fem_json(Contact::SolveResult{}, context());
    EXPECT_EQ(Output::force_balance_text(none), "force balance: no increment");
  }

  // The sentence names the largest force and the round-off bound, each
  // with 2 significant digits, and the fraction 1e-10.
  TEST(FemReport, NoLoadTextStatesBothForces)
  {
    Compare::LoadCheck check;
    check.largest_force   = 1.234e-3;
    check.round_off_force = 1.6e-2;
    const std::string text = Output::no_load_text(check);
    EXPECT_NE(text.find("every joint force are at most 1.2e-03 N/m"),
              std::string::npos)
      << text;
    EXPECT_NE(text.find("(1e-10 E |u|max = 1.6e-02 N/m)"), std::string::npos)
      << text;
  }
} // namespace
