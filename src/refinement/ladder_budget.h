#pragma once

#include <refinement/level_record.h>

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Refinement
{
  /** @brief What a refinement study may spend: wall time and mesh size. */
  struct LadderBudget
  {
    /** Wall time left for the ladder (s). */
    double seconds = std::numeric_limits<double>::infinity();
    /** Largest number of DoFs a level may have. */
    std::size_t max_dofs = std::numeric_limits<std::size_t>::max();
  };

  /** @brief The expected size and wall time of the next level. */
  struct LevelForecast
  {
    double n_dofs    = 0.; ///< DoFs
    double wall_time = 0.; ///< s
  };

  /**
   * DoF growth of the first refinement step before any is observed: every
   * cell of a 2D mesh halved.
   */
  constexpr double first_step_dof_growth = 4.;
  /**
   * Wall-time exponent of the first step, t ~ N^1.3: what the sparse LU
   * factorisations and the growing Newton counts of the contact solve
   * give on the default scene (0.7, 3.4, 16, 68 s at 5.5k, 21k, 79k,
   * 312k DoFs: ratios 4.9, 4.7, 4.2 per factor 3.85 of DoFs).
   */
  constexpr double first_step_time_exponent = 1.3;

  /**
   * @brief The next level from the levels so far: the last step's growth
   * of DoFs and of wall time repeated, or for a single level
   * first_step_dof_growth and N^first_step_time_exponent.
   * Pre-condition: @p levels is not empty.
   */
  LevelForecast
  forecast_next_level(const std::vector<LevelRecord> &levels);

  /**
   * @brief Why the next level does not fit the budget, or nothing if it
   * does: @p forecast needs more DoFs than @p budget allows, or more wall
   * time than is left after @p spent_seconds.
   */
  std::optional<std::string>
  budget_stop_reason(const LadderBudget  &budget,
                     const double         spent_seconds,
                     const LevelForecast &forecast);
} // namespace FloorBlock::Refinement
