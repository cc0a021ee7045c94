#pragma once

#include <convergence/level_record.h>
#include <convergence/richardson.h>

#include <optional>
#include <string>

namespace FloorBlock::Convergence
{
  /** @brief A refinement ladder and the error estimate of each quantity. */
  struct Ladder
  {
    std::string                 mode; ///< "uniform" or "adaptive"
    std::vector<LevelRecord>    levels;
    std::vector<SequenceErrors> errors; ///< one per quantities_of_interest() entry
  };

  /** @brief Estimates the errors of every quantity of a ladder. */
  void
  estimate_ladder_errors(Ladder &ladder, const std::vector<Quantity> &quantities);

  /** @brief Cost of uniform and adaptive refinement at one error level. */
  struct EqualErrorComparison
  {
    std::string quantity;
    double      target_relative_error = 0.;
    /** Common reference value of both ladders, and where it comes from. */
    std::optional<double> reference;
    std::string           reference_source;
    /** First level from which on every finer level is within the target. */
    std::optional<unsigned int> uniform_level;
    std::optional<unsigned int> adaptive_level;
    /** Adaptive over uniform at those levels: DoFs, cost wall time. */
    std::optional<double> dofs_ratio;
    std::optional<double> cost_ratio;
  };

  /**
   * @brief Compares both ladders against one common reference value, so
   * that "equal error" means the same thing for both: the uniform
   * Richardson value if the uniform ladder converges regularly, else the
   * adaptive one, else the converged value with the most DoFs of either
   * ladder (which then has error 0 by construction: a bias towards that
   * ladder, stated in reference_source). The relative error of a level is
   * |q - reference| / |reference|; each ladder's level is the first from
   * which on all finer converged levels stay within @p target_relative_error
   * (a non-converged finer level breaks the run).
   */
  EqualErrorComparison
  compare_at_equal_error(const Ladder   &uniform,
                         const Ladder   &adaptive,
                         const Quantity &quantity,
                         const std::size_t quantity_index,
                         const double   target_relative_error);
} // namespace FloorBlock::Convergence
