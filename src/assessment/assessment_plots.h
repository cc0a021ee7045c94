#pragma once

#include <assessment/assessment.h>

#include <string>

namespace FloorBlock::Assessment
{
  /**
   * @brief gnuplot script of assess_fs.png: the histogram and the
   * cumulative distribution of FS over the inputs (the surrogate's sample),
   * FS = 1 and P(FS < 1) marked, the FEM cases' FS beside them.
   */
  std::string
  safety_factor_distribution_plot(const AssessmentResult &result);

  /**
   * @brief gnuplot script of assess_sobol.png: first-order and total
   * Sobol' indices per input as bars with their 95 % intervals.
   */
  std::string
  sobol_indices_plot(const AssessmentResult &result);

  /**
   * @brief gnuplot script of assess_fs_inputs.png: the FEM cases' FS
   * against the two inputs of largest total index (or the one input), FS =
   * 1 marked.
   */
  std::string
  safety_factor_inputs_plot(const AssessmentResult &result);

  /**
   * @brief gnuplot script of assess_design_limit.png: P(FS < 1) against
   * the design limit input with its 95 % band, the target probabilities
   * and where they are reached (result.design_limit must be set).
   */
  std::string
  design_limit_plot(const AssessmentResult &result);
} // namespace FloorBlock::Assessment
