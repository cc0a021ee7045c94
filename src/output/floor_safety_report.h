#pragma once

#include <safety/corner_safety.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /**
   * @brief fem.json "floor_safety": L, every corner's point- and
   * line-method factors (safety_factor_point, safety_factor_line) with the
   * principal stresses they come from, and the governing corner.
   */
  nlohmann::json
  floor_safety_json(const std::vector<Safety::CornerSafety> &corners);

  /**
   * @brief floor_safety_paths.csv: along every corner's path, the
   * distance, the principal stresses (compression positive) and the
   * strength factor of the stress there, for plots of FS against the
   * distance from the corner.
   */
  std::string
  floor_safety_paths_csv(const std::vector<Safety::CornerSafety> &corners);

  /** @brief The terminal's line: the governing corner, both factors and
   * whether the corner holds. Empty without corners. */
  std::string
  floor_safety_text(const std::vector<Safety::CornerSafety> &corners);
} // namespace FloorBlock::Output
