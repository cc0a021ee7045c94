#pragma once

#include <common/input_error.h>
#include <parameters/scenario_parameters.h>

#include <refinement/size_targets.h>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace FloorBlock::App
{
  /** What every subcommand takes from the command line. */
  struct CommandOptions
  {
    std::string              scene_path = "params/default.prm";
    std::vector<std::string> overrides;         ///< "Subsection/Entry=value"
    std::string              output_directory;  ///< empty: results/<scene>/
    bool                     print_ids = false; ///< mesh: print the id scheme
    bool                     with_fem  = false; ///< sweep: also run the FEM
    std::string              verification_case; ///< verify: e.g. "hertz"
    std::string              figure;            ///< sweep: only this figure
    unsigned int             case_limit = 0; ///< sweep --fem: at most this many
    /// sweep --fem: only grid points with these k (m; 0 = planar); empty: all.
    std::vector<double> curvatures;
    /// sweep --fem: only grid points with a support load in [first, second]
    /// (t); empty: all.
    std::vector<double> load_range;
    /** converge: ladder length; 0 = not given (default_levels, time-budgeted).
     */
    unsigned int n_levels = 0;
    std::string  refinement_mode =
      "both"; ///< converge: uniform|adaptive|remesh|both|all
    double bulk_fraction =
      0.1; ///< converge: cells refined by the Kelly indicator
    double coarsen_fraction =
      Refinement::default_coarsen_fraction; ///< converge adaptive: cells
                                            ///< flagged for coarsening
    double jump_fraction = 0.25; ///< converge: joint traction-jump threshold
    double target_error =
      0.01; ///< converge: relative error of the equal-error comparison
    /** converge: wall time of the whole study (s); NaN = not given. */
    double      budget_seconds = std::numeric_limits<double>::quiet_NaN();
    std::size_t max_dofs       = 400000; ///< converge: largest level (DoFs)
    /** converge: FE degrees, one set of ladders each; empty = the scene's. */
    std::vector<unsigned int> fe_degrees;
  };

  /** @brief Reads the scene with its overrides (throws InputError). */
  Parameters::ScenarioParameters
  read_scene(const CommandOptions &options);

  /**
   * @brief Refuses a 3D scene (Geometry/Dimension = 3) for @p command,
   * which solves in plane strain only: InputError naming the parameter.
   */
  void
  require_plane_scene(const Parameters::ScenarioParameters &scene,
                      const std::string                    &command);

  /** @brief --output if given, otherwise results/<scene name>. */
  std::string
  output_directory(const CommandOptions                 &options,
                   const Parameters::ScenarioParameters &scene);

  int
  print_parameters_command(const CommandOptions &options);
  int
  analytic_command(const CommandOptions &options);
  int
  sweep_command(const CommandOptions &options);
  int
  mesh_command(const CommandOptions &options);
  int
  solve_command(const CommandOptions &options);
  int
  verify_command(const CommandOptions &options);
  int
  run_command(const CommandOptions &options);
  int
  converge_command(const CommandOptions &options);
  int
  corner_command(const CommandOptions &options);
  int
  assess_command(const CommandOptions &options);
} // namespace FloorBlock::App
