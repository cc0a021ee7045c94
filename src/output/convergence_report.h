#pragma once

#include <nlohmann/json.hpp>
#include <refinement/equal_error.h>

#include <optional>
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
  convergence_csv(const std::vector<Refinement::Ladder>   &ladders,
                  const std::vector<Refinement::Quantity> &quantities);

  /**
   * @brief convergence.json: per mode the levels and, per quantity, the
   * error method with its reason, the observed orders, the reference value
   * and the errors; then the equal-error comparisons.
   */
  nlohmann::json
  convergence_json(
    const std::vector<Refinement::Ladder>               &ladders,
    const std::vector<Refinement::Quantity>             &quantities,
    const std::vector<Refinement::EqualErrorComparison> &comparisons);

  /** Whether a refinement mode meets the target against uniform. */
  struct TargetVerdict
  {
    /** False when the comparison lacks the uniform or the mode's ladder. */
    bool        evaluated = false;
    bool        met       = false;
    std::string text; ///< per quantity: levels, DoF and time ratios
    /** Target: at most this fraction of the uniform DoFs ... */
    double dofs_ratio_limit = 0.;
    /** ... and at most this fraction of its wall time (exclusive). */
    double cost_ratio_limit = 0.;

    /** @brief "met", "not met" or "not evaluated". */
    std::string
    status() const;
  };

  /**
   * @brief {"status", "text"} of a verdict, with the two limits when it
   * was evaluated.
   */
  nlohmann::json
  target_verdict_json(const TargetVerdict &verdict);

  /**
   * @brief The final convergence.json: convergence_json() with the verdict
   * on the adaptive target ("adaptive_target") and, with --mode all, on the
   * remesh target ("remesh_target").
   */
  nlohmann::json
  convergence_study_json(
    const std::vector<Refinement::Ladder>               &ladders,
    const std::vector<Refinement::Quantity>             &quantities,
    const std::vector<Refinement::EqualErrorComparison> &comparisons,
    const TargetVerdict                                 &adaptive_target,
    const std::optional<TargetVerdict>                  &remesh_target);

  /** @brief converge's summary.json, written last. */
  nlohmann::json
  convergence_summary_json(const std::string   &scene_name,
                           const bool           all_converged,
                           const TargetVerdict &adaptive_target,
                           const double         wall_time);

  /**
   * @brief Terminal lines of one ladder: per quantity the error method,
   * the order used by the extrapolation, the reference value and why.
   */
  std::string
  ladder_text(const Refinement::Ladder                &ladder,
              const std::vector<Refinement::Quantity> &quantities);

  /**
   * @brief gnuplot script: relative error estimate against the cost wall
   * time, log-log, one curve per quantity and mode (uniform solid, adaptive
   * dashed). Levels without an estimate, or with one at round-off level
   * (Refinement::round_off_level), are left out.
   */
  std::string
  error_vs_time_plot(const std::vector<Refinement::Ladder>   &ladders,
                     const std::vector<Refinement::Quantity> &quantities,
                     const std::string                       &title);
} // namespace FloorBlock::Output
