// The output rule for closed-form values: a value whose mechanism or corner
// contact status is not `ok` is left empty in every CSV and is never shown
// as `[ok]` on the terminal. Checked on the default scene and on a site
// scene (tests/cli/site_scene.prm) whose mechanisms are mostly
// inadmissible.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>
#include <sstream>

#include "process.h"

using namespace FloorBlockTest;

namespace
{
  const std::vector<std::string> status_scenes = {"params/default.prm",
                                                  "tests/cli/site_scene.prm"};

  const std::vector<std::string> mechanism_names = {"no_rotation",
                                                    "rotation_no_vertical_slip",
                                                    "rotation_vertical_slip"};

  bool
  starts_with(const std::string &text, const std::string &prefix)
  {
    return text.compare(0, prefix.size(), prefix) == 0;
  }

  /** Eqs. 6.51-6.53 cells and the safety factor from them: they need the
   * contact status as well. */
  bool
  is_corner_contact_column(const std::string &column)
  {
    return column.find("_A_m2") != std::string::npos ||
           column.find("_sigma") != std::string::npos ||
           column.find("_safety_factor") != std::string::npos;
  }

  /**
   * Every non-empty cell of a mechanism's column (name prefix) in every row
   * of @p path must sit in a row where that mechanism's status column says
   * ok, and a corner-contact cell also where its contact status says ok.
   * @return The number of non-ok statuses met, so a caller can make sure
   * the check was not vacuous.
   */
  unsigned int
  check_cells_against_statuses(const std::string &path)
  {
    const CsvTable table = read_csv(path);
    EXPECT_FALSE(table.columns.empty()) << path;
    unsigned int n_not_ok = 0;
    for (std::size_t r = 0; r < table.rows.size(); ++r)
      {
        const CsvRow &row = table.rows[r];
        for (const std::string &mechanism : mechanism_names)
          {
            const auto status = row.find(mechanism + "_status");
            if (status == row.end())
              continue;
            const auto contact = row.find(mechanism + "_contact_status");
            n_not_ok += status->second != "ok";
            for (const auto &[column, field] : row)
              {
                if (!starts_with(column, mechanism + "_") ||
                    column.size() >= 6 &&
                      column.compare(column.size() - 6, 6, "status") == 0 ||
                    field.empty())
                  continue;
                EXPECT_EQ(status->second, "ok")
                  << path << " row " << r + 1 << ": " << column << " = "
                  << field << " although " << mechanism
                  << "_status = " << status->second;
                if (contact != row.end() && is_corner_contact_column(column))
                  EXPECT_EQ(contact->second, "ok")
                    << path << " row " << r + 1 << ": " << column << " = "
                    << field << " although " << mechanism
                    << "_contact_status = " << contact->second;
              }
          }
      }
    return n_not_ok;
  }

  /** Every CSV under @p folder, checked; the number of non-ok statuses. */
  unsigned int
  check_every_csv(const std::string &folder)
  {
    unsigned int n_csv = 0, n_not_ok = 0;
    for (const auto &entry :
         std::filesystem::recursive_directory_iterator(folder))
      if (entry.path().extension() == ".csv")
        {
          ++n_csv;
          n_not_ok += check_cells_against_statuses(entry.path().string());
        }
    EXPECT_GT(n_csv, 0u) << folder;
    return n_not_ok;
  }

  std::string
  status_run(const std::string &command,
             const std::string &scene,
             std::string       *terminal  = nullptr,
             const std::string &overrides = "")
  {
    const std::string folder = fresh_output_folder(
      "status_" + command + "_" + std::filesystem::path(scene).stem().string());
    const auto result = run_floorblock(command + " " + scene + " --output " +
                                       shell_quoted(folder));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    if (terminal)
      *terminal = result.output;
    return folder;
  }
} // namespace

// The tool shall leave every closed-form cell of analytic.csv empty where the
// mechanism's status is not ok.
TEST(ClosedFormStatus, AnalyticCsvHoldsOnlyAdmissibleValues)
{
  for (const std::string &scene : status_scenes)
    {
      const std::string folder = status_run("analytic", scene);
      EXPECT_GT(check_every_csv(folder), 0u) << scene;
      std::filesystem::remove_all(folder);
    }
}

// The tool shall print no face-joint line marked [ok] for a mechanism whose
// status is not ok.
TEST(ClosedFormStatus, AnalyticTerminalMarksNoInadmissibleValueOk)
{
  for (const std::string &scene : status_scenes)
    {
      std::string        terminal;
      const std::string  folder = status_run("analytic", scene, &terminal);
      const auto         cases  = read_json(folder + "/analytic.json")["cases"];
      std::istringstream lines(terminal);
      std::string        line, current;
      while (std::getline(lines, line))
        {
          for (const std::string &mechanism : mechanism_names)
            if (starts_with(line, mechanism + ": "))
              current = mechanism;
          if (!current.empty() && line.find("[ok]") != std::string::npos)
            EXPECT_EQ(cases[current]["status"], "ok")
              << scene << ": " << current << ": " << line;
        }
      std::filesystem::remove_all(folder);
    }
}

// The tool shall leave every closed-form cell of the sweep CSVs empty where
// the mechanism's status or its corner contact's status is not ok.
TEST(ClosedFormStatus, SweepCsvHoldsOnlyAdmissibleValues)
{
  for (const std::string &scene : status_scenes)
    {
      const std::string folder = status_run("sweep", scene);
      EXPECT_GT(check_every_csv(folder), 0u) << scene;
      std::filesystem::remove_all(folder);
    }
}

// The tool shall leave every closed-form cell of run's CSVs empty where the
// mechanism's status is not ok.
TEST(ClosedFormStatus, RunCsvHoldsOnlyAdmissibleValues)
{
  // One solve per scene: the rule does not depend on the error estimate.
  const std::string one_solve =
    " --set 'Solver/Error estimate=none' --set 'Solver/FE degree=1'";
  for (const std::string &scene : status_scenes)
    {
      const std::string folder = status_run("run", scene, nullptr, one_solve);
      EXPECT_GT(check_every_csv(folder), 0u) << scene;
      std::filesystem::remove_all(folder);
    }
}
