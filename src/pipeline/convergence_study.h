#pragma once

#include <convergence/equal_error.h>
#include <output/convergence_report.h>
#include <pipeline/convergence_ladder.h>

#include <string>
#include <vector>

namespace FloorBlock::Pipeline
{
  /** Target: adaptive needs at most this fraction of the uniform DoFs ... */
  constexpr double target_dofs_ratio = 0.25;
  /** ... and less than this fraction of its wall time. */
  constexpr double target_cost_ratio = 1.;

  /**
   * @brief The ladders of `converge --mode @p choice`: uniform, adaptive,
   * remesh, both (uniform and adaptive) or all.
   */
  std::vector<RefinementMode>
  refinement_modes(const std::string &choice);

  /**
   * @brief Every further ladder against the first (when it is the uniform
   * one), per quantity, at the relative error @p target_error.
   */
  std::vector<Convergence::EqualErrorComparison>
  equal_error_comparisons(const std::vector<Convergence::Ladder>   &ladders,
                          const std::vector<Convergence::Quantity> &quantities,
                          const double target_error);

  /**
   * @brief Whether the ladder @p adaptive_mode ("adaptive" or "remesh")
   * reaches the face joint's contact length and averaged peak stress at
   * the target error with at most target_dofs_ratio of the uniform DoFs in
   * less time; not evaluated without both ladders.
   */
  Output::TargetVerdict
  target_verdict(
    const std::vector<Convergence::EqualErrorComparison> &comparisons,
    const std::string                                    &adaptive_mode);
  /**
   * @brief One line per quantity comparing the uniform ladders of FE
   * degree 2 ("uniform_q2") and 1 ("uniform") at equal error: the level
   * each needs, DoFs and time ratio, and which degree gets there faster;
   * "" without a degree-2 ladder.
   */
  std::string
  degree_comparison_text(
    const std::vector<Convergence::EqualErrorComparison> &comparisons);
} // namespace FloorBlock::Pipeline
