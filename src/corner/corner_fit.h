#pragma once

#include <analytic/asymptotic_fit.h>
#include <corner/corner_theory.h>

#include <vector>

namespace FloorBlock::Corner
{
  /**
   * @brief Distances from the edge over which a refinement level's traction
   * is mesh-converged: the longest run of consecutive samples of @p fine,
   * from the edge outwards, whose traction differs from @p coarse's
   * (interpolated linearly in log t against log d) by at most @p tolerance
   * relative, among the samples with @p from_at_least <= d <= @p up_to.
   * from = to = 0 when there is no such run of at least 4 samples.
   */
  struct DistanceRange
  {
    double       from      = 0.; ///< m
    double       to        = 0.; ///< m
    unsigned int n_samples = 0;
  };
  DistanceRange
  converged_range(const std::vector<Analytic::RadialSample> &fine,
                  const std::vector<Analytic::RadialSample> &coarse,
                  double                                     tolerance,
                  double                                     from_at_least,
                  double                                     up_to);

  /** @brief The samples with from <= d <= to. */
  std::vector<Analytic::RadialSample>
  samples_within(const std::vector<Analytic::RadialSample> &samples,
                 const DistanceRange                       &range);

  /** @brief K1 and K2 of a fit with every exponent given. */
  struct Intensities
  {
    double first  = 0.; ///< K1 (Pa m^(1 - lambda1))
    double second = 0.; ///< K2 (Pa m^(1 - lambda2))
  };

  /**
   * @brief K1, K2 of the theory's expansion (its exponent, next and third
   * exponents all given; Analytic::fixed_exponent_fit()): K1 is the
   * leading term's intensity, the figure compared between refinement
   * levels; fitting the further terms keeps it from absorbing them where
   * the range reaches beyond the one-term field. Zeros when the fit is
   * singular.
   */
  Intensities
  theory_intensities(const std::vector<Analytic::RadialSample> &samples,
                     const CornerTheory                        &theory);

  /** @brief Every fit of the traction near a corner's edge. */
  struct CornerFit
  {
    DistanceRange range;
    /**
     * t = K1 d^(lambda1 - 1) + K2 d^(lambda2 - 1) + K3 d^(lambda3 - 1),
     * lambda1 fitted, lambda2 and lambda3 the theory's next exponents
     * (Analytic::expansion_fit()): the fitted exponent. Two terms where
     * the theory has no third.
     */
    Analytic::AsymptoticFit expansion;
    /** The same with two terms, for comparison. */
    Analytic::AsymptoticFit two_terms;
    /** 1 + the slope of log t against log d. */
    Analytic::AsymptoticFit one_term;
    /** K1, K2 with both exponents the theory's. */
    Intensities intensity;
    /** Distance within which the first term alone describes the two-term field
     * within 10 % (m). */
    double validity_distance = 0.;
  };

  /**
   * @brief lambda1 of the mean pressure near the edge: the theory's
   * expansion as for the traction, plus a constant (the lambda = 1 mode,
   * a uniform stress, is part of the bulk field although it puts no
   * traction on a smooth edge).
   */
  Analytic::AsymptoticFit
  fit_invariant(const std::vector<Analytic::RadialSample> &samples,
                const DistanceRange                       &range,
                const CornerTheory                        &theory);

  /** @brief The fits of @p samples over @p range for @p theory. */
  CornerFit
  fit_corner(const std::vector<Analytic::RadialSample> &samples,
             const DistanceRange                       &range,
             const CornerTheory                        &theory);
} // namespace FloorBlock::Corner
