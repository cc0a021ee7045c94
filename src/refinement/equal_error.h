#pragma once

#include <refinement/level_record.h>
#include <refinement/richardson.h>

#include <optional>
#include <string>

namespace FloorBlock::Refinement
{
  /** @brief A refinement ladder and the error estimate of each quantity. */
  struct Ladder
  {
    std::string              mode; ///< "uniform" or "adaptive"
    std::vector<LevelRecord> levels;
    std::vector<SequenceErrors>
      errors; ///< one per quantities_of_interest() entry
    /** Why the ladder ended before its last requested level (budget); empty
     * otherwise. */
    std::string stopped_because;
  };

  /** @brief Estimates the errors of every quantity of a ladder. */
  void
  estimate_ladder_errors(Ladder                      &ladder,
                         const std::vector<Quantity> &quantities);

  /** @brief Cost of uniform and adaptive refinement at one error level. */
  struct EqualErrorComparison
  {
    std::string quantity;
    /** The refined ladder compared with uniform refinement ("adaptive" or
     * "remesh"). */
    std::string adaptive_mode;
    double      target_relative_error = 0.;
    /**
     * First level from which on every finer level with an estimate has an
     * estimated relative error within the target (each ladder's own
     * estimate, as in convergence.csv and the plot).
     */
    std::optional<unsigned int> uniform_level;
    std::optional<unsigned int> adaptive_level;
    /**
     * Adaptive over uniform at those levels: DoFs, cost wall time. If only
     * the adaptive ladder reaches the target, the uniform ladder would need
     * more than its finest converged level: the ratios to that level are
     * then upper bounds (ratios_are_upper_bounds).
     */
    std::optional<double> dofs_ratio;
    std::optional<double> cost_ratio;
    bool                  ratios_are_upper_bounds = false;
    /**
     * |uniform reference - adaptive reference| / |uniform reference|: the
     * two ladders' best values (Richardson or finest level). Larger than the
     * target means that at least one ladder's own estimate misses part of
     * its error, and the comparison above is not at equal error.
     */
    std::optional<double> reference_difference;
  };

  /**
   * @brief The levels at which each ladder first reaches (and keeps) an
   * estimated relative error of at most @p target_relative_error for
   * quantity @p quantity_index, their DoF and cost ratios, and how far the
   * two ladders' best values lie apart. A ladder whose non-converged level
   * follows breaks the run (it has no estimate there and the next level
   * starts over).
   */
  EqualErrorComparison
  compare_at_equal_error(const Ladder     &uniform,
                         const Ladder     &adaptive,
                         const Quantity   &quantity,
                         const std::size_t quantity_index,
                         const double      target_relative_error);
} // namespace FloorBlock::Refinement
