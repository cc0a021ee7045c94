// Figures 6.10/6.11 with the scene rock's strength: the closed-form sweep
// writes the rock mass strength sigma_c and the chapter's safety factor
// sigma_c / sigma_max (Eq. 6.53) beside each sigma_max; `sweep --fem`
// writes the FEM's critical-distance stress at the face corner beside
// them.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "process.h"

using namespace FloorBlockTest;

namespace
{
  const std::vector<std::string> swept_mechanisms =
    {"no_rotation", "rotation_no_vertical_slip", "rotation_vertical_slip"};

  // The CSV's numbers carry ten significant digits: the quotient of two
  // rounded numbers differs from the rounded factor by at most 1.5e-10.
  constexpr double sweep_csv_tolerance = 1e-9;

  // The tool shall write, per point of Figures 6.10/6.11, the scene rock's
  // strength sigma_c (analytic.json's floor_strength_Pa) and per mechanism
  // FS = sigma_c / sigma_max, present exactly where sigma_max is a
  // positive, admissible number.
  TEST(SweepStrength, ClosedFormSafetyFactorBesideEverySigmaMax)
  {
    const std::string scene  = "params/default.prm --set "
                               "\"Strength/Intact UCS=60e6\"";
    const std::string folder = fresh_output_folder("sweep_strength");
    const auto        sweep =
      run_floorblock("sweep " + scene + " --output " + shell_quoted(folder));
    ASSERT_EQ(sweep.exit_code, 0) << sweep.output;
    const auto analytic = run_floorblock("analytic " + scene + " --output " +
                                         shell_quoted(folder + "/analytic"));
    ASSERT_EQ(analytic.exit_code, 0) << analytic.output;
    const double strength =
      read_json(folder + "/analytic/analytic.json")["floor_strength_Pa"];

    const CsvTable table = read_csv(folder + "/sweep_fig6_10_11.csv");
    ASSERT_EQ(table.rows.size(), 144u);
    unsigned int n_factors = 0, n_below_one = 0;
    for (const CsvRow &row : table.rows)
      {
        EXPECT_NEAR(number_in(row, "floor_strength_Pa") / strength,
                    1.,
                    sweep_csv_tolerance);
        for (const std::string &mechanism : swept_mechanisms)
          {
            const std::string stress = row.at(mechanism + "_sigma_max_Pa");
            const std::string factor =
              row.at(mechanism + "_safety_factor_eq_6_53");
            ASSERT_EQ(!factor.empty(),
                      !stress.empty() && std::stod(stress) > 0.)
              << mechanism << ": sigma_max '" << stress << "', factor '"
              << factor << "'";
            if (factor.empty())
              continue;
            ++n_factors;
            n_below_one += std::stod(factor) < 1.;
            EXPECT_NEAR(std::stod(factor) * std::stod(stress) /
                          number_in(row, "floor_strength_Pa"),
                        1.,
                        sweep_csv_tolerance)
              << mechanism;
          }
      }
    // sigma_c = 14.9 MPa cuts through the default scene's curves: at
    // k = 400 m some cases hold, at k = 50 m none does.
    EXPECT_GT(n_factors, 0u);
    EXPECT_GT(n_below_one, 0u);
    EXPECT_LT(n_below_one, n_factors);
    for (const char *curvature : {"400", "200", "100", "50"})
      EXPECT_TRUE(std::filesystem::exists(folder + "/sweep_fig6_10_11_k" +
                                          curvature + ".png"));
    std::filesystem::remove_all(folder);
  }

  // The first FEM case of Figures 6.10/6.11 on three blocks: k = 400 m,
  // phi_h = 10 deg, 400 t. A critical distance of 5 cm in cells of L/8
  // resolves the face corner; the solve takes about a second.
  const std::string first_stress_case =
    " tests/scenarios/three_blocks.prm --set \"Strength/Critical "
    "distance=0.05\"";
  const std::string resolving_cells =
    " --set \"Mesh/Cells per critical distance=8\"";

  // The tool shall write, per FEM case of Figures 6.10/6.11, the FEM's
  // sigma_1 at L/2 at the face corner and its point-method factor, the
  // numbers `solve` of the same point writes in fem.json for the face
  // block's corner, beside Eq. 6.53's sigma_max and its factor.
  TEST(SweepStrength, FemFaceCornerBesideEquation653)
  {
    const std::string folder = fresh_output_folder("sweep_strength_fem");
    const auto        sweep  = run_floorblock(
      "sweep" + first_stress_case + resolving_cells +
      " --fem --figure fig6_10_11 --limit 1 --output " + shell_quoted(folder));
    ASSERT_EQ(sweep.exit_code, 0) << sweep.output;
    EXPECT_TRUE(std::filesystem::exists(folder + "/sweep_fem_fig6_10_11.png"));
    const CsvTable table = read_csv(folder + "/sweep_fem_fig6_10_11.csv");
    ASSERT_EQ(table.rows.size(), 1u);
    const CsvRow &row = table.rows.front();
    ASSERT_EQ(row.at("fem_status"), "converged");
    ASSERT_EQ(row.at("fem_face_corner_status"), "resolved");
    const double sigma_1 = number_in(row, "fem_sigma_1_at_half_L_Pa");
    const double factor  = number_in(row, "fem_safety_factor_point");
    EXPECT_GT(sigma_1, 0.);
    EXPECT_TRUE(std::isfinite(factor) && factor > 0.) << factor;
    EXPECT_NEAR(number_in(row, "no_rotation_safety_factor_eq_6_53") *
                  number_in(row, "no_rotation_sigma_max_6_53_Pa") /
                  number_in(row, "floor_strength_Pa"),
                1.,
                sweep_csv_tolerance);

    const std::string solved = folder + "/solve";
    const auto        solve  = run_floorblock(
      "solve" + first_stress_case + resolving_cells +
      " --set \"Joints/Bedding friction angle=10\" --set \"Loading/Support "
              "load=400\" --output " +
      shell_quoted(solved));
    ASSERT_EQ(solve.exit_code, 0) << solve.output;
    const nlohmann::json fem            = read_json(solved + "/fem.json");
    unsigned int         n_face_corners = 0;
    for (const auto &corner : fem["floor_safety"]["corners"])
      if (corner["block"] == "face block")
        {
          ++n_face_corners;
          EXPECT_NEAR(sigma_1 / corner["sigma_1_at_half_L_Pa"].get<double>(),
                      1.,
                      sweep_csv_tolerance);
          EXPECT_NEAR(factor / corner["safety_factor_point"].get<double>(),
                      1.,
                      sweep_csv_tolerance);
        }
    EXPECT_EQ(n_face_corners, 1u);
    std::filesystem::remove_all(folder);
  }

  // The tool shall leave the face corner's numbers empty, saying
  // unresolved, where the mesh does not resolve the critical distance.
  TEST(SweepStrength, UnresolvedFaceCornerCarriesNoNumber)
  {
    const std::string folder = fresh_output_folder("sweep_strength_coarse");
    const auto        sweep =
      run_floorblock("sweep" + first_stress_case +
                     " --set \"Mesh/Cells per critical distance=0\" --fem "
                     "--figure fig6_10_11 --limit 1 --output " +
                     shell_quoted(folder));
    ASSERT_EQ(sweep.exit_code, 0) << sweep.output;
    const CsvTable table = read_csv(folder + "/sweep_fem_fig6_10_11.csv");
    ASSERT_EQ(table.rows.size(), 1u);
    const CsvRow &row = table.rows.front();
    EXPECT_EQ(row.at("fem_face_corner_status"), "unresolved");
    EXPECT_TRUE(row.at("fem_sigma_1_at_half_L_Pa").empty());
    EXPECT_TRUE(row.at("fem_safety_factor_point").empty());
    EXPECT_FALSE(row.at("no_rotation_safety_factor_eq_6_53").empty());
    std::filesystem::remove_all(folder);
  }
} // namespace
