#pragma once

#include <openturns/Distribution.hxx>
#include <openturns/Function.hxx>
#include <openturns/Sample.hxx>

#include <cstdint>
#include <string>

namespace FloorBlock::Uncertainty
{
  /** @brief A fitted surrogate of one output and what its fit says of its
   * error. */
  struct Surrogate
  {
    OT::Function model; ///< inputs (their units) -> output
    /** Which candidate the cross validation chose, in words. */
    std::string kind;
    /** Total degree of the chaos; 0 for kriging. */
    std::uint64_t chaos_degree = 0;
    /**
     * Root mean square of the k-fold cross-validation residuals: each
     * fold predicted by a surrogate fitted (terms selected, kriging
     * scales optimised anew) on the other folds.
     */
    double        cross_validation_rms = 0.;
    std::uint64_t n_folds              = 0;
    /**
     * The error the surrogate states for a new point: a split-conformal
     * bound, the ceil((n + 1) 0.95)-th smallest of the n cross-validation
     * residuals' magnitudes. A new point drawn like the fitted ones lies
     * within it with probability at least 95 % whatever the residuals'
     * distribution (their largest magnitude when n < 19).
     */
    double stated_error = 0.;
  };

  /**
   * @brief The surrogate of @p outputs over @p inputs with the smallest
   * @p n_folds-fold cross-validation error (points dealt to the folds in
   * turn, every fold refitted) among:
   * - sparse polynomial chaos (OpenTURNS' FunctionalChaosAlgorithm) of
   *   total degree 1 to @p max_chaos_degree: Hermite polynomials of the
   *   inputs' normal scores (the iso-probabilistic transformation of
   *   @p distribution, so a lognormal stiffness enters through its
   *   logarithm), terms chosen by LARS under the corrected leave-one-out
   *   error;
   * - kriging (OpenTURNS' KrigingAlgorithm) in the same normal scores: a
   *   linear trend and a Matern 5/2 covariance whose scales and amplitude
   *   are fitted by maximum likelihood. It follows an output whose slope
   *   changes abruptly (a governing corner that switches, a joint that
   *   starts to slip), which a polynomial spreads over the whole space.
   *
   * That error is the surrogate's. A candidate whose fit throws on some
   * fold drops out.
   * @throws std::invalid_argument if the samples' sizes or dimensions do
   *   not match @p distribution, or there are fewer points than inputs + 2.
   * @throws std::runtime_error if no candidate can be fitted, naming why
   *   each failed.
   */
  Surrogate
  fit_surrogate(const OT::Sample       &inputs,
                const OT::Sample       &outputs,
                const OT::Distribution &distribution,
                std::uint64_t           max_chaos_degree,
                std::uint64_t           n_folds = 10);

  /** @brief How a surrogate predicts points it was not fitted on. */
  struct HeldOutErrors
  {
    std::uint64_t n_points = 0;
    double        rms      = 0.; ///< of prediction - truth
    double        largest  = 0.; ///< |prediction - truth|
    /** Share of the points predicted within @p stated_error (-). */
    double share_within_stated = 0.;
  };

  /**
   * @brief The surrogate's errors on held-out points (@p inputs,
   * @p outputs), and the share of them within @p stated_error.
   */
  HeldOutErrors
  held_out_errors(const OT::Function &surrogate,
                  const OT::Sample   &inputs,
                  const OT::Sample   &outputs,
                  double              stated_error);
} // namespace FloorBlock::Uncertainty
