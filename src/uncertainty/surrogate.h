#pragma once

#include <openturns/Distribution.hxx>
#include <openturns/Function.hxx>
#include <openturns/Sample.hxx>

#include <cstdint>

namespace FloorBlock::Uncertainty
{
  /** @brief A fitted surrogate of one output and what its fit says of its
   * error. */
  struct Surrogate
  {
    OT::Function model; ///< inputs (their units) -> output
    /** Largest total degree of its polynomials. */
    std::uint64_t degree = 0;
    /** Terms LARS kept. */
    std::uint64_t n_terms = 0;
    /**
     * Root mean square of the corrected leave-one-out residuals of the fit
     * (OpenTURNS' CorrectedLeaveOneOut relative error times the output's
     * variance), in the output's units: the error expected at a new point.
     */
    double leave_one_out_rms = 0.;
    /**
     * Root mean square of the k-fold cross-validation residuals: each
     * fold predicted by a surrogate fitted (degree chosen and terms
     * selected anew) on the other folds.
     */
    double cross_validation_rms = 0.;
    /**
     * The error the surrogate states for a new point: the 95 % quantile of
     * the cross-validation residuals' magnitudes. The leave-one-out error
     * of the selected terms is optimistic (the terms were chosen to make
     * it small), the refitted folds are not.
     */
    double        stated_error = 0.;
    std::uint64_t n_folds      = 0;
  };

  /**
   * @brief A sparse polynomial chaos of @p outputs over @p inputs (OpenTURNS'
   * FunctionalChaosAlgorithm): Hermite polynomials of the inputs' normal
   * scores (the iso-probabilistic transformation of @p distribution, so a
   * lognormal stiffness enters through its logarithm), terms chosen by
   * LARS under the corrected leave-one-out error, of the total degree from
   * 1 to @p max_degree whose @p n_folds-fold cross-validation error (points
   * dealt to the folds in turn, every fold refitted) is smallest; that
   * error is the surrogate's.
   * @throws std::invalid_argument if the samples' sizes or dimensions do
   *   not match @p distribution, or there are fewer points than inputs + 2.
   */
  Surrogate
  fit_chaos_surrogate(const OT::Sample       &inputs,
                      const OT::Sample       &outputs,
                      const OT::Distribution &distribution,
                      std::uint64_t           max_degree,
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
