// `floorblock converge` end to end on the coarse 3-block scene: 3 uniform,
// 3 adaptive (hanging nodes) and 3 remesh levels (about 10 s on the 2-core
// test machine), and the adaptive ladder on rounded corners. CTest runs
// every TEST in its own process, so the study's checks share one TEST and
// one run.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

namespace
{
  const std::vector<std::string> ladder_modes = {"uniform",
                                                 "adaptive",
                                                 "remesh"};

  // The tool shall record every level of all three ladders with its mesh, cost,
  // quantities of interest and error estimate, units in the column names.
  void
  check_every_level_and_column(const std::string &output)
  {
    for (const char *name : {"convergence.csv",
                             "convergence.json",
                             "error_vs_wall_time.png",
                             "summary.json",
                             "uniform/level_2/fem.json",
                             "adaptive/level_2/mesh.msh",
                             "remesh/level_2/mesh.msh"})
      EXPECT_TRUE(std::filesystem::exists(output + "/" + name)) << name;

    const CsvTable table = read_csv(output + "/convergence.csv");
    for (const char *column : {"mode",
                               "level",
                               "status",
                               "converged",
                               "n_cells",
                               "n_dofs",
                               "n_increments",
                               "newton_iterations",
                               "force_balance_relative_error",
                               "wall_time_mesh_s",
                               "wall_time_assemble_s",
                               "wall_time_linear_solve_s",
                               "wall_time_s",
                               "cost_wall_time_s",
                               "Q_1_N_per_m",
                               "Q_2_N_per_m",
                               "Q_face_N_per_m",
                               "Q_face_error_N_per_m",
                               "Q_face_relative_error",
                               "Q_face_error_method",
                               "contact_length_face_m",
                               "contact_length_face_error_m",
                               "sigma_max_face_Pa",
                               "sigma_max_averaged_face_Pa",
                               "sigma_max_averaged_face_error_Pa",
                               "status_text"})
      EXPECT_NE(std::find(table.columns.begin(), table.columns.end(), column),
                table.columns.end())
        << column;

    ASSERT_EQ(table.rows.size(), 9u);
    for (std::size_t k = 0; k < table.rows.size(); ++k)
      {
        const CsvRow &row = table.rows[k];
        EXPECT_EQ(row.at("mode"), ladder_modes[k / 3]);
        EXPECT_EQ(row.at("level"), std::to_string(k % 3));
        EXPECT_EQ(row.at("status"), "converged") << row.at("status_text");
        for (const auto &[column, value] : row)
          EXPECT_FALSE(has_non_finite_value(value)) << column << " = " << value;
      }
    // All ladders start from the same mesh.
    EXPECT_EQ(table.rows[0].at("n_dofs"), table.rows[3].at("n_dofs"));
    EXPECT_EQ(table.rows[0].at("n_dofs"), table.rows[6].at("n_dofs"));
  }

  // The tool shall refine: uniform levels multiply the DoFs (each halves
  // every cell of the level before, so 4 times the cells and, with the
  // nodes shared between cells, about 3.6 times the DoFs here), adaptive and
  // remesh levels add some; the adaptive levels' meshes are local deal.II
  // refinements of the level before (n_refinement_sweeps >= 1), the remesh
  // levels Gmsh meshes, the uniform ones global refinements of level 0
  // (no sweeps counted).
  void
  check_levels_refine(const std::string &output)
  {
    const CsvTable table = read_csv(output + "/convergence.csv");
    ASSERT_EQ(table.rows.size(), 9u);
    for (std::size_t k : {1u, 2u})
      {
        EXPECT_GT(number_in(table.rows[k], "n_dofs"),
                  3. * number_in(table.rows[k - 1], "n_dofs"));
        EXPECT_EQ(number_in(table.rows[k], "n_cells"),
                  4. * number_in(table.rows[k - 1], "n_cells"));
        EXPECT_EQ(number_in(table.rows[k], "global_refinements"),
                  number_in(table.rows[k - 1], "global_refinements") + 1.);
      }
    for (std::size_t k : {4u, 5u, 7u, 8u})
      EXPECT_GT(number_in(table.rows[k], "n_dofs"),
                number_in(table.rows[k - 1], "n_dofs"));
    for (std::size_t k : {4u, 5u})
      {
        EXPECT_GT(number_in(table.rows[k], "n_local_sizes"), 0.);
        EXPECT_GE(number_in(table.rows[k], "n_refinement_sweeps"), 1.);
      }
    // Only adaptive levels count refinement sweeps.
    for (std::size_t k : {0u, 1u, 2u, 6u, 7u, 8u})
      EXPECT_EQ(number_in(table.rows[k], "n_refinement_sweeps"), 0.);
  }

  // The tool shall converge in the joint force Q at the face. Q is a
  // resultant of the joint tractions, and the contact README's refinement
  // study measured changes of at most 0.1 % per halving for corner sizes up to
  // 0.04 m (6-block scene); this ladder's finest step goes from 0.05 to
  // 0.025 m, so 0.25 % leaves room for the coarser start without hiding a
  // method that fails to converge (the first halving changes Q by about
  // 0.5 %, and the finest change must also be smaller than that one).
  void
  check_face_force_converges(const std::string &output)
  {
    const CsvTable table = read_csv(output + "/convergence.csv");
    ASSERT_EQ(table.rows.size(), 9u);
    const auto q = [&](const std::size_t k) {
      return number_in(table.rows[k], "Q_face_N_per_m");
    };
    constexpr double tolerance = 2.5e-3;
    EXPECT_LT(std::abs(q(2) - q(1)), tolerance * std::abs(q(2)));
    EXPECT_LT(std::abs(q(2) - q(1)), std::abs(q(1) - q(0)));
    // The adaptive and remesh ladders end within the same 0.25 % of the
    // uniform ladder's finest Q (measured: 2.0e-3 adaptive, 1.2e-3 remesh;
    // the uniform finest step 6.7e-5): a bound on how far two
    // discretisations of Q may disagree at this coarse start, not a claim
    // that they agree to their own step size.
    EXPECT_LT(std::abs(q(5) - q(2)), tolerance * std::abs(q(2)));
    EXPECT_LT(std::abs(q(8) - q(2)), tolerance * std::abs(q(2)));
  }

  // The tool shall state for every quantity how its error was estimated.
  void
  check_methods_and_orders(const std::string &output)
  {
    const json report = read_json(output + "/convergence.json");
    for (const std::string &mode : ladder_modes)
      for (const auto &[name, estimate] :
           report["modes"][mode]["quantities"].items())
        {
          const std::string method = estimate["method"];
          EXPECT_TRUE(method == "richardson" || method == "finest_difference")
            << mode << " " << name << ": " << method;
          EXPECT_FALSE(estimate["reason"].get<std::string>().empty());
          EXPECT_EQ(estimate["observed_orders"].size(), 3u);
        }
    // Q_1, Q_2, Q_face + 3 face figures, adaptive and remesh each against
    // uniform.
    ASSERT_EQ(report["equal_error_comparison"].size(), 12u);
    EXPECT_EQ(report["equal_error_comparison"][0]["mode"], "adaptive");
    EXPECT_EQ(report["equal_error_comparison"][6]["mode"], "remesh");
    EXPECT_TRUE(report.contains("adaptive_target"));
    EXPECT_TRUE(report.contains("remesh_target"));
  }

} // namespace

// The tool shall run uniform, adaptive and remesh refinement ladders and
// report each level's cost, answers and error estimate.
TEST(ConvergeCommand, StudyOfTheThreeBlockScene)
{
  const std::string folder = fresh_output_folder("converge_three_blocks");
  const auto        result = run_floorblock(
    "converge tests/scenarios/three_blocks.prm --levels 3 --mode all "
           "--output " +
    shell_quoted(folder));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  check_every_level_and_column(folder);
  check_levels_refine(folder);
  check_face_force_converges(folder);
  check_methods_and_orders(folder);
}

// The tool shall refine rounded corners with hanging nodes: the facing top
// fillets (mirror images on this level floor) and the joints' common parts
// get the same new nodes on both sides, so every level pairs and solves.
// A pairing that lost a partner would fail the level ("failed"); a level
// whose new fillet vertices left the arcs would still solve, which the
// geometry unit test RefinementManifolds covers.
TEST(ConvergeCommand, AdaptiveLadderOnRoundedCorners)
{
  const std::string folder = fresh_output_folder("converge_rounded");
  const auto        result = run_floorblock(
    "converge tests/scenarios/hard_rounded_corners.prm --levels 3 --mode "
           "adaptive --output " +
    shell_quoted(folder));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const CsvTable table = read_csv(folder + "/convergence.csv");
  ASSERT_EQ(table.rows.size(), 3u);
  for (std::size_t k = 0; k < table.rows.size(); ++k)
    {
      const CsvRow &row = table.rows[k];
      EXPECT_EQ(row.at("status"), "converged") << row.at("status_text");
      // Equilibrium of every body holds on the refined meshes as on Gmsh's.
      EXPECT_LT(number_in(row, "force_balance_relative_error"), 1e-8);
      if (k > 0)
        {
          EXPECT_GT(number_in(row, "n_contact_pairs"),
                    number_in(table.rows[k - 1], "n_contact_pairs"));
          // Q at the face stays within 1 % of level 0 (measured 0.16 % and
          // 0.17 %): refining the corners moves the joint force little,
          // as on the uniform ladder of the three-block study (0.5 % at
          // the first halving); a broken pairing or load moves it more.
          EXPECT_LT(std::abs(number_in(row, "Q_face_N_per_m") /
                               number_in(table.rows[0], "Q_face_N_per_m") -
                             1.),
                    0.01);
        }
    }
  EXPECT_FALSE(std::filesystem::exists(folder + "/uniform"));
}

// The tool shall stop a ladder before a level its budget cannot pay for,
// say why, and still write the study of the levels it ran.
TEST(ConvergeCommand, StopsBeforeALevelBeyondTheBudget)
{
  const std::string folder = fresh_output_folder("converge_budget");
  // A forecast of 4 times the DoFs of level 0 is above 1000 DoFs.
  const auto result = run_floorblock(
    "converge tests/scenarios/three_blocks.prm --levels 3 --mode uniform "
    "--max-dofs 1000 --output " +
    shell_quoted(folder));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("stopped before level 1"), std::string::npos)
    << result.output;
  const CsvTable table = read_csv(folder + "/convergence.csv");
  EXPECT_EQ(table.rows.size(), 1u);
  std::ifstream     json(folder + "/convergence.json");
  const std::string text((std::istreambuf_iterator<char>(json)),
                         std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("above --max-dofs 1000"), std::string::npos);
}

// The tool shall refuse a budget that pays for nothing.
TEST(ConvergeCommand, RefusesAZeroBudget)
{
  const std::string folder = fresh_output_folder("converge_zero_budget");
  const auto        result = run_floorblock(
    "converge tests/scenarios/three_blocks.prm --budget-seconds 0 --output " +
    shell_quoted(folder));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("--budget-seconds"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(folder));
}

// The tool shall refuse a ladder too short for any error estimate.
TEST(ConvergeCommand, RefusesOneLevel)
{
  const std::string folder = fresh_output_folder("converge_one_level");
  const auto        result = run_floorblock(
    "converge tests/scenarios/three_blocks.prm --levels 1 --output " +
    shell_quoted(folder));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("--levels"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(folder));
}

// Issue 14: the tool shall run the ladders with both FE degrees when asked,
// keep them apart (uniform, uniform_q2: rows, level folders) and compare the
// degrees at equal error, naming the faster one.
TEST(ConvergeCommand, BothDegreesSideBySide)
{
  const std::string folder = fresh_output_folder("converge_degrees");
  const auto        result = run_floorblock(
    "converge tests/scenarios/three_blocks.prm --levels 2 --mode uniform "
           "--degrees 1,2 --output " +
    shell_quoted(folder));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  const CsvTable table = read_csv(folder + "/convergence.csv");
  ASSERT_EQ(table.rows.size(), 4u);
  EXPECT_EQ(table.rows[0].at("mode"), "uniform");
  EXPECT_EQ(table.rows[2].at("mode"), "uniform_q2");
  // Same cells, about 3.8 times the DoFs at degree 2 (Q2 has 9 nodes a cell).
  EXPECT_EQ(number_in(table.rows[2], "n_cells"),
            number_in(table.rows[0], "n_cells"));
  EXPECT_GT(number_in(table.rows[2], "n_dofs"),
            3. * number_in(table.rows[0], "n_dofs"));
  EXPECT_TRUE(std::filesystem::exists(folder + "/uniform_q2/level_1"));
  EXPECT_NE(result.output.find("FE degrees at 1 % error"), std::string::npos)
    << result.output;
  EXPECT_NE(result.output.find("faster: degree"), std::string::npos)
    << result.output;
}

TEST(ConvergeCommand, RefusesAnUnknownDegree)
{
  const std::string folder = fresh_output_folder("converge_degree_3");
  const auto        result = run_floorblock(
    "converge tests/scenarios/three_blocks.prm --degrees 1,3 --output " +
    shell_quoted(folder));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("--degrees"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(folder));
}
