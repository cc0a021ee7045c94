#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "process.h"

using namespace FloorBlockTest;
using nlohmann::json;

// `mpirun -np 2 floorblock assess` deals the FEM cases to both processes
// (each case on one) and gives the one-process study: the same cases to
// the last digit (each case solves alone, whichever process runs it) and
// the same P(FS < 1), FORM and Sobol' answer (every process runs the same
// seeded OpenTURNS algorithms on the same records).
TEST(AssessMpi, TwoProcessesGiveTheOneProcessAnswer)
{
  const std::string arguments = "assess tests/cli/assess_scene.prm --output ";
  const std::string folder_1  = fresh_output_folder("assess_mpi_1");
  const std::string folder_2  = fresh_output_folder("assess_mpi_2");
  const auto        one = run_floorblock(arguments + shell_quoted(folder_1));
  ASSERT_EQ(one.exit_code, 0) << one.output;
  const auto two =
    run_floorblock_on_processes(2, arguments + shell_quoted(folder_2), 600);
  ASSERT_EQ(two.exit_code, 0) << two.output;
  // Both processes solved cases.
  EXPECT_NE(two.output.find("[rank 0]"), std::string::npos) << two.output;
  EXPECT_NE(two.output.find("[rank 1]"), std::string::npos) << two.output;

  json answer_1 = read_json(folder_1 + "/assess.json");
  json answer_2 = read_json(folder_2 + "/assess.json");
  answer_1.erase("cost_by_model");
  answer_2.erase("cost_by_model");
  EXPECT_EQ(answer_1, answer_2);
  EXPECT_GT(answer_1.at("failure_probability").at("estimate").get<double>(),
            0.);

  const CsvTable cases_1 = read_csv(folder_1 + "/cases.csv");
  const CsvTable cases_2 = read_csv(folder_2 + "/cases.csv");
  ASSERT_EQ(cases_1.rows.size(), 6u);
  ASSERT_EQ(cases_2.rows.size(), 6u);
  for (std::size_t k = 0; k < cases_1.rows.size(); ++k)
    for (const auto &[column, value] : cases_1.rows[k])
      if (column != "wall_time_s")
        EXPECT_EQ(cases_2.rows[k].at(column), value)
          << "row " << k << ", " << column;
}
