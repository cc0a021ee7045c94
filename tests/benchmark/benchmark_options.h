#pragma once

#include <string>
#include <vector>

namespace FloorBlock::Benchmark
{
  /** @brief The benchmark's own flags (Google Benchmark parses the rest). */
  struct BenchmarkOptions
  {
    /** Scene read with the project's parameter reader. */
    std::string scene_path;
    /** "Subsection/Entry=value" overrides applied to the scene. */
    std::vector<std::string> overrides;
    /** Mesh/Corner size and Mesh/Far size are divided by each of these. */
    std::vector<double> refinements = {0.5, 1., 2., 4., 8.};
    /** Joint laws of the whole contact solve. */
    std::vector<std::string> joint_laws = {"compliant", "rigid"};
    /** HertzSettings::cells_per_half_width of the Hertz runs. */
    std::vector<unsigned int> hertz_cells_per_half_width = {16, 32, 64};
    /**
     * A law's contact solve on the next finer mesh is skipped once one
     * level took longer than this (wall, s).
     */
    double level_time_limit = 120.;
    /** Where the .msh files go (a fresh folder under the temp directory). */
    std::string work_directory;
  };

  /**
   * @brief Takes --scene=, --set= (repeatable), --refinements=, --laws=,
   * --hertz_levels= and --level_time_limit= out of argv (the rest stays for
   * Google Benchmark).
   * @throws InputError naming the flag and the bad value.
   */
  BenchmarkOptions
  parse_options(int &argc, char **argv, const std::string &default_scene);

  /** @brief Flag help appended to Google Benchmark's --help. */
  std::string
  options_help();
} // namespace FloorBlock::Benchmark
