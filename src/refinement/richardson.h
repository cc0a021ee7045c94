#pragma once

#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Refinement
{
  /** How the discretisation error of a quantity was estimated. */
  enum class ErrorMethod
  {
    /** Extrapolation from the last three levels with the observed order. */
    richardson,
    /** Irregular convergence: the difference to the finest usable level. */
    finest_difference,
    /** Fewer than two usable levels: no estimate. */
    unavailable
  };

  /** @brief "richardson", "finest_difference", "unavailable". */
  std::string
  method_name(const ErrorMethod method);

  /**
   * Largest accepted change of the observed order between the last two
   * triples of levels, for the convergence to count as regular: orders 1 and
   * 2 differ by one. Units: 1 (order).
   */
  constexpr double order_consistency_band = 1.0;

  /**
   * Differences between levels below this fraction of the value are
   * round-off (a quantity fixed by equilibrium alone, e.g. Q_1 of a free
   * end block), not discretisation error: no order is observed from them.
   * Units: 1 (relative to |q_L|); double precision leaves about 1e-16 per
   * operation, the assembled solves some 1e-12.
   */
  constexpr double round_off_level = 1e-10;

  /** @brief Error estimate of one quantity over a refinement ladder. */
  struct SequenceErrors
  {
    ErrorMethod method = ErrorMethod::unavailable;
    /** Why this method, in words (which test failed, if any). */
    std::string reason;
    /**
     * Observed order of each level l with levels l-2, l-1, l usable:
     * \f$p_l = \log_2(|q_{l-1} - q_{l-2}| / |q_l - q_{l-1}|)\f$, defined
     * when both differences are non-zero and have the same sign.
     */
    std::vector<std::optional<double>> observed_orders;
    /** Richardson value (richardson) or the finest usable value
     * (finest_difference). */
    std::optional<double> reference;
    /** Absolute error estimate per level; empty for unusable levels and, with
     * finest_difference, for the finest level itself. */
    std::vector<std::optional<double>> errors;
    /** errors / |reference|; empty where errors is, or if reference is 0. */
    std::vector<std::optional<double>> relative_errors;
  };

  /**
   * @brief Estimates the error of every level of a sequence q_0, q_1, ...
   * in which each level halves the element size of the one before.
   *
   * Richardson extrapolation
   * \f$q_\infty = q_L + (q_L - q_{L-1}) / (2^p - 1)\f$ with the observed
   * order p of the finest three levels L-2, L-1, L is used when the
   * convergence is regular: those three levels are usable and consecutive,
   * p is defined and positive, the last two differences exceed
   * round_off_level, and, if level L-3 is usable too, its order
   * p_{L-1} is defined and within order_consistency_band of p (the two
   * difference ratios agree). The error of level l is then
   * \f$|q_l - q_\infty|\f$. Otherwise the error of level l < L is the
   * difference to the finest usable level, \f$|q_l - q_L|\f$, and level L
   * has none. With \f$2^p\f$ read as the observed ratio of successive
   * differences, the same extrapolation (Aitken's) holds for any ladder
   * whose differences shrink geometrically, e.g. adaptive re-meshing.
   *
   * @param[in] values One entry per level; empty for a level that did not
   *   converge (it is never used).
   */
  SequenceErrors
  estimate_errors(const std::vector<std::optional<double>> &values);
} // namespace FloorBlock::Refinement
