#pragma once

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace FloorBlockTest
{
  /**
   * A coarse mesh for the 3D scenes: about 3.5k DoFs per cross-section,
   * 10.5k in 3D on params/plane_strain_3d.prm, a few seconds a solve.
   */
  inline const std::string coarse_3d_mesh =
    " --set 'Mesh/Cells per contact length=2' --set 'Mesh/Corner size=0.1'"
    " --set 'Mesh/Far size=0.5'";

  /** What a finished floorblock process left behind. */
  struct ProcessResult
  {
    int         exit_code;
    std::string output; ///< stdout and stderr together
  };

  /**
   * @brief Runs build/floorblock with @p arguments (already shell-quoted)
   * from the source folder, so relative scene paths resolve as in the README.
   */
  ProcessResult
  run_floorblock(const std::string &arguments);

  /**
   * @brief run_floorblock() under the MPI launcher on @p n_processes
   * processes (`mpiexec -n N`, as CMake's FindMPI names it; allowed to run
   * as root and on more processes than cores). With @p time_limit_seconds
   * the launcher is ended after that long (coreutils `timeout`: exit code
   * 124), so that a test of a hang fails instead of hanging.
   */
  ProcessResult
  run_floorblock_on_processes(const unsigned int n_processes,
                              const std::string &arguments,
                              unsigned int       time_limit_seconds = 0);

  /**
   * @brief Starts build/floorblock with @p arguments in the background
   * (output to @p log_path) and returns its process id.
   */
  int
  start_floorblock(const std::string &arguments, const std::string &log_path);

  /** @brief Waits for a started process; its exit code (-1 if killed). */
  int
  wait_for_exit(const int process_id);

  /** @brief A fresh, not yet existing folder under the system temp folder. */
  std::string
  fresh_output_folder(const std::string &name);

  /** @brief A JSON file parsed (throws if it is missing or malformed). */
  nlohmann::json
  read_json(const std::string &path);

  /** One row of a CSV table: column name -> field. */
  using CsvRow = std::map<std::string, std::string>;

  /** @brief A CSV table: its header and its rows. */
  struct CsvTable
  {
    std::vector<std::string> columns;
    std::vector<CsvRow>      rows;
  };

  /**
   * @brief A CSV file as written by floorblock: '#' lines are comments, the
   * first other line is the header; fields in double quotes may hold
   * commas. Empty if the file cannot be read.
   */
  CsvTable
  read_csv(const std::string &path);

  /** @brief A field of @p row as a number (throws if absent or not numeric). */
  double
  number_in(const CsvRow &row, const std::string &column);

  /** @brief The whole text of a file ("" if it cannot be read). */
  std::string
  read_text(const std::string &path);

  /**
   * @brief True if @p text holds a non-finite number as a value: "nan" or
   * "inf" (fmt's spelling, any case, optional sign) not part of a word, so
   * "information" does not count. nlohmann::json writes NaN/inf as null;
   * check nulls separately where they are not allowed.
   */
  bool
  has_non_finite_value(const std::string &text);

  /** @brief Quotes @p text for the shell. */
  std::string
  shell_quoted(const std::string &text);
} // namespace FloorBlockTest
