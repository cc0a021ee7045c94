#pragma once

#include <convergence/equal_error.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /**
   * @brief convergence.csv: one row per mode and level. Columns: mesh
   * (sizes, cells, DoFs), solver effort, wall time per stage
   * (wall_time_<stage>_s), wall_time_s, cost_wall_time_s, and per quantity
   * its value (<name>_<unit>), error estimate (<name>_error_<unit>,
   * <name>_relative_error) and the method of the estimate
   * (<name>_error_method). Fields without a value (non-converged level, no
   * estimate) are empty; status and status_text say why.
   */
  std::string
  convergence_csv(const std::vector<Convergence::Ladder>   &ladders,
                  const std::vector<Convergence::Quantity> &quantities);

  /**
   * @brief convergence.json: per mode the levels and, per quantity, the
   * error method with its reason, the observed orders, the reference value
   * and the errors; then the equal-error comparisons.
   */
  nlohmann::json
  convergence_json(const std::vector<Convergence::Ladder>   &ladders,
                   const std::vector<Convergence::Quantity> &quantities,
                   const std::vector<Convergence::EqualErrorComparison>
                     &comparisons);

  /**
   * @brief gnuplot script: relative error estimate against the cost wall
   * time, log-log, one curve per quantity and mode (uniform solid, adaptive
   * dashed). Levels without an estimate, or with one at round-off level
   * (Convergence::round_off_level), are left out.
   */
  std::string
  error_vs_time_plot(const std::vector<Convergence::Ladder>   &ladders,
                     const std::vector<Convergence::Quantity> &quantities,
                     const std::string                        &title);
} // namespace FloorBlock::Output
