#pragma once

#include <parameters/scenario_parameters.h>

#include <assessment/safety_cases.h>
#include <openturns/Distribution.hxx>
#include <openturns/Sample.hxx>
#include <uncertainty/reliability.h>
#include <uncertainty/sensitivity.h>
#include <uncertainty/surrogate.h>

#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace FloorBlock::Assessment
{
  /** @brief A model's share of the study's work. */
  struct ModelCost
  {
    std::string   model; ///< "fem", "surrogate"
    std::uint64_t evaluations = 0;
    /** Of them, those an earlier run computed (FEM records reused). */
    std::uint64_t from_earlier_runs = 0;
    double        wall_time         = 0.; ///< s, summed over the evaluations
  };

  /** @brief P(FS < 1) from a model, with what bounds it. */
  struct FailureEstimate
  {
    Uncertainty::FailureProbability monte_carlo; ///< with its 95 % interval
    /**
     * P(FS e^e < 1) and P(FS e^-e < 1) for the surrogate's stated error e
     * of ln FS: where P_f may lie if the surrogate errs by that factor
     * near FS = 1.
     */
    double lower_with_surrogate_error = 0.;
    double upper_with_surrogate_error = 0.;
  };

  /** @brief P(FS < 1) with one input fixed, over that input's range. */
  struct DesignLimit
  {
    std::size_t input = 0; ///< index into the inputs
    /** The input's values (its 1 % to 99 % quantiles), and P(FS < 1) with
     * its 95 % half-width at each. */
    std::vector<double>                          values;
    std::vector<Uncertainty::FailureProbability> probabilities;
    /** Each target P(FS < 1) and the value where the curve reaches it
     * (linear between grid points), or none: not reached in the range. */
    std::vector<std::pair<double, std::optional<double>>> limits;
  };

  /** @brief Everything `assess` found. */
  struct AssessmentResult
  {
    std::vector<Parameters::UncertainInput>   inputs;
    std::vector<Parameters::InputCorrelation> correlations;
    std::vector<SafetyCase>                   training;
    std::vector<SafetyCase>                   validation;
    /** Of ln FS; its errors are of ln FS (a factor on FS). */
    Uncertainty::Surrogate     surrogate;
    Uncertainty::HeldOutErrors held_out;
    FailureEstimate            failure;
    Uncertainty::DesignPoint   design_point;
    /** Of the surrogate over the inputs' marginals taken independent. */
    Uncertainty::SobolIndices sobol;
    std::vector<ModelCost>    costs;
    /** The surrogate's FS (not its log) at every training and validation
     * case. */
    std::vector<double> surrogate_at_training, surrogate_at_validation;
    /** FS of the surrogate at random draws of the inputs, for the
     * distribution's pictures. */
    std::vector<double> surrogate_fs_sample;
    /** Over Uncertainty/Design limit input, if it is an input. */
    std::optional<DesignLimit> design_limit;
  };

  /** @brief The study ended early: what it had done by its time budget. */
  struct AssessmentIncomplete
  {
    unsigned int n_cases_done  = 0;
    unsigned int n_cases_total = 0;
  };

  /**
   * @brief The solved cases' inputs (in their units) and ln FS, as the
   * surrogate is fitted and checked on. The surrogate models ln FS: a
   * safety factor is a ratio of strength to stress, which the rock's
   * strength and the loads scale, so its logarithm is nearly linear in the
   * logarithms of lognormal inputs (their normal scores) where FS itself
   * bends; its error is then a factor on FS.
   */
  std::pair<OT::Sample, OT::Sample>
  solved_samples(const std::vector<SafetyCase> &cases, std::size_t dimension);

  /**
   * @brief Checks the study's inputs without computing: the joint
   * distribution (throws InputError for Uncertainty/Correlations that are
   * not positive definite) and at least one uncertain input.
   */
  OT::Distribution
  checked_input_distribution(const Parameters::ScenarioParameters &scene);

  /**
   * @brief The probability of floor failure of @p scene under its
   * Uncertainty subsection: FEM cases on a Latin hypercube (the
   * surrogate's training) and on random draws (held out), stored in
   * @p case_folder and resumed from it, over the ranks of MPI_COMM_WORLD;
   * a polynomial chaos of ln FS (the verdict's safety factor) fitted on
   * them; then
   * on the surrogate, P(FS < 1) by Monte Carlo to Uncertainty/Failure
   * probability half width, FORM's design point and Sobol' indices.
   * @return false (and @p incomplete filled) if the time budget ended
   *   the FEM cases first.
   */
  bool
  run_assessment(const Parameters::ScenarioParameters &scene,
                 const SceneSource                    &source,
                 const std::string                    &case_folder,
                 std::ostream                         &progress,
                 AssessmentResult                     &result,
                 AssessmentIncomplete                 &incomplete);
} // namespace FloorBlock::Assessment
