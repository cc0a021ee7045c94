#pragma once

#include <output/comparison_report.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /** The governing corner's safety factors at one increment of the lift. */
  struct LiftSafety
  {
    double      base_lift = 0.; ///< m
    std::string corner;           ///< the governing corner
    double      point_factor   = 0.;
    double      line_factor    = 0.;
    double      area_factor    = 0.;
    double      verdict_factor = 0.; ///< the factor the verdict goes by
    std::string verdict_method;      ///< "line" or "area"
  };

  /**
   * @brief The governing corner (smallest verdict factor among the
   * resolved ones, Safety::verdict_factor()) at every increment of
   * @p history that resolves one.
   */
  std::vector<LiftSafety>
  safety_along_lift(const std::vector<LiftHistoryPoint> &history);

  /**
   * @brief The floor lift at which the governing corner's verdict factor
   * first reaches 1, linear between the increments around it; none if it
   * stays above 1, or is below 1 from the lift's first increment on (then
   * the floor fails before the lift, under its weight and the supports).
   */
  std::optional<double>
  lift_at_unit_safety(const std::vector<LiftSafety> &along);

  /**
   * @brief summary.json's floor_safety.along_lift: lift_m,
   * safety_factor_point, safety_factor_line and safety_factor_area
   * (governing corner per increment), verdict_method,
   * lift_at_safety_factor_1_m (absent if none) and its text.
   */
  nlohmann::json
  safety_along_lift_json(const std::vector<LiftSafety> &along);

  /** @brief One sentence: where FS reaches 1 along the lift, if it does. */
  std::string
  unit_safety_text(const std::vector<LiftSafety> &along);

  /** @brief gnuplot script of floor_safety_vs_lift.png (FS = 1 drawn). */
  std::string
  safety_along_lift_plot(const std::vector<LiftSafety> &along);
} // namespace FloorBlock::Output
