#pragma once

#include <vector>

namespace FloorBlock::Analytic
{
  /** @brief A traction sample at distance r from a corner (m, Pa). */
  struct RadialSample
  {
    double distance;
    double traction;
  };

  /** @brief p(r) = K1 r^(lambda1 - 1) (+ K2 r^(lambda2 - 1)). */
  struct AsymptoticFit
  {
    double lambda1 = 0.;
    double k1      = 0.; ///< Pa m^(1 - lambda1)
    double k2      = 0.; ///< Pa m^(1 - lambda2); 0 for the one-term fit
    double lambda2 = 0.; ///< given; 0 for the one-term fit
    /** Root-mean-square of the relative residuals (p_fit - p) / p. */
    double rms_relative_residual = 0.;
    unsigned int n_samples       = 0;
  };

  /**
   * @brief The straight line through log p against log r (least squares):
   * lambda1 = 1 + slope. Needs at least 2 samples with r, p > 0 (else all
   * zero).
   */
  AsymptoticFit
  one_term_fit(const std::vector<RadialSample> &samples);

  /**
   * @brief Two terms of the corner's eigen-expansion, the second
   * exponent @p lambda2 given (from the eigen-solver), lambda1, K1 and K2
   * fitted: minimises the relative residuals sum ((p_fit - p) / p)^2; for
   * each lambda1 the K's follow by linear least squares (variable
   * projection), lambda1 itself from a scan of (0.01, lambda2 - 0.01)
   * in steps of 1e-3, refined by golden-section search.
   *
   * Why two terms: where the second exponent lies close to the first (a
   * square block edge stuck on a similar half-plane: 0.5445 and 0.9085),
   * the second term decays only as r^0.36 relative to the first and
   * biases a one-term fit at every resolvable distance (measured in
   * `verify punch`: one-term 0.59-0.62, two-term 0.53-0.545).
   */
  AsymptoticFit
  two_term_fit(const std::vector<RadialSample> &samples, double lambda2);

  /**
   * @brief Distance within which the first term alone describes the
   * two-term field within @p relative (|K2/K1| r^(lambda2 - lambda1) <=
   * relative), m; infinite when K2 = 0.
   */
  double
  one_term_validity_distance(const AsymptoticFit &fit, double relative);
} // namespace FloorBlock::Analytic
