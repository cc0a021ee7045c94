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
    double       rms_relative_residual = 0.;
    unsigned int n_samples             = 0;
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
   * @brief Several terms of the eigen-expansion: lambda1 fitted, the
   * exponents of the further terms given (@p further, from the
   * eigen-solver), every K by linear least squares in the relative
   * residual (variable projection), lambda1 scanned over
   * (@p scan_from, @p scan_to) in steps of 1e-3 and refined by golden-
   * section search. Returns lambda1, K1 and, as lambda2 and K2, the first
   * further term (the one the validity distance compares with).
   *
   * Why more than two: at a smooth contact edge the exponents 3/2, 2, 5/2
   * lie 1/2 apart, so over a fit range that reaches a fair fraction of
   * the zone the third term still biases a two-term fit (measured on
   * `floorblock corner`: 1.531 and 1.554 with two terms, theory 1.5).
   */
  AsymptoticFit
  expansion_fit(const std::vector<RadialSample> &samples,
                const std::vector<double>       &further,
                double                           scan_from,
                double                           scan_to);

  /**
   * @brief The K's of the terms with the exponents @p lambdas, all given
   * (at most 4), by linear least squares in the relative residual: lambda1,
   * K1 of the first, lambda2, K2 of the second (0 without one). Residual
   * infinite for a singular system (too few samples, equal exponents).
   */
  AsymptoticFit
  fixed_exponent_fit(const std::vector<RadialSample> &samples,
                     const std::vector<double>       &lambdas);

  /**
   * @brief Distance within which the first term alone describes the
   * two-term field within @p relative (|K2/K1| r^(lambda2 - lambda1) <=
   * relative), m; infinite when K2 = 0.
   */
  double
  one_term_validity_distance(const AsymptoticFit &fit, double relative);
} // namespace FloorBlock::Analytic
