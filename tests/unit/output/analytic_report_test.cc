// analytic.csv: the header lines, one column group per mechanism, one row
// per block in the chapter's numbering, numbers with 10 significant digits
// and empty cells where a mechanism has no answer.
#include <analytic/block_chain.h>
#include <analytic/status.h>
#include <output/analytic_report.h>
#include <output/numbering_note.h>
#include <scene/closed_forms.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace FloorBlock;

  std::vector<std::string>
  split(const std::string &text, const char separator)
  {
    std::vector<std::string> parts;
    std::istringstream       stream(text);
    for (std::string part; std::getline(stream, part, separator);)
      parts.push_back(part);
    // getline drops a trailing empty field: keep it, it is an empty cell.
    if (!text.empty() && text.back() == separator)
      parts.emplace_back();
    return parts;
  }

  /**
   * Two blocks of W = 90 kN/m on a 0.1 rad bed, P = 245.16625 kN/m on
   * block 2; no_rotation answers Q = (123456.789, 200000) N/m, the
   * rotation without vertical slip is self-locking (no values).
   */
  Scene::ClosedForms
  two_block_closed_forms()
  {
    Scene::ClosedForms forms;
    forms.chain = Analytic::uniform_chain(2, 90e3, 0., 0.1, 1., 2., 0.5, 0.5);
    forms.chain.support_load[1] = 245166.25;
    forms.support_width         = 1.5;
    forms.youngs_modulus        = 16e9;
    forms.floor_lift            = 0.01;

    Scene::MechanismResult no_rotation;
    no_rotation.mechanism            = Scene::Mechanism::no_rotation;
    no_rotation.forces.lateral_force = {123456.789, 200e3};
    no_rotation.forces.normal_force  = {90e3, 335166.25};
    Scene::MechanismResult locked;
    locked.mechanism     = Scene::Mechanism::rotation_no_vertical_slip;
    locked.forces.status = Analytic::Status::self_locking;
    forms.mechanisms     = {no_rotation, locked};
    forms.no_rotation_heights.centroid_height = {0.75, 1.25};
    return forms;
  }

  TEST(AnalyticCsv, HeaderLinesAndColumnGroups)
  {
    const auto lines =
      split(Output::analytic_csv(two_block_closed_forms()), '\n');
    // 2 comment lines, the column names, 2 blocks and the final newline.
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[0], std::string("# ") + Output::numbering_note);
    EXPECT_EQ(lines[1].rfind("# Forces per metre of face;", 0), 0u) << lines[1];
    EXPECT_EQ(lines[2],
              "block,W_N_per_m,P_N_per_m,alpha_deg,"
              "no_rotation_status,no_rotation_Q_N_per_m,no_rotation_N_N_per_m,"
              "rotation_no_vertical_slip_status,"
              "rotation_no_vertical_slip_Q_N_per_m,"
              "rotation_no_vertical_slip_N_N_per_m,no_rotation_h_m");
    EXPECT_EQ(lines[5], "");
  }

  TEST(AnalyticCsv, OneRowPerBlockWithEmptyCellsWithoutAnswer)
  {
    const auto lines =
      split(Output::analytic_csv(two_block_closed_forms()), '\n');
    ASSERT_GE(lines.size(), 5u);
    const auto first = split(lines[3], ',');
    ASSERT_EQ(first.size(), 11u) << lines[3];
    EXPECT_EQ(first[0], "1");
    EXPECT_EQ(first[1], "9.000000000e+04");
    EXPECT_EQ(first[2], "0.000000000e+00");
    // 0.1 rad = 5.729578 degrees (6 decimals written).
    EXPECT_NEAR(std::stod(first[3]), 0.1 * 180. / M_PI, 5e-7);
    EXPECT_EQ(first[4], Analytic::to_string(Analytic::Status::ok));
    EXPECT_EQ(first[5], "1.234567890e+05");
    EXPECT_EQ(first[6], "9.000000000e+04");
    EXPECT_EQ(first[7], Analytic::to_string(Analytic::Status::self_locking));
    EXPECT_EQ(first[8], "");
    EXPECT_EQ(first[9], "");
    EXPECT_EQ(first[10], "7.500000000e-01");

    const auto second = split(lines[4], ',');
    ASSERT_EQ(second.size(), 11u) << lines[4];
    EXPECT_EQ(second[0], "2");
    EXPECT_EQ(second[2], "2.451662500e+05");
    EXPECT_EQ(second[5], "2.000000000e+05");
    EXPECT_EQ(second[6], "3.351662500e+05");
    EXPECT_EQ(second[10], "1.250000000e+00");
  }
} // namespace
