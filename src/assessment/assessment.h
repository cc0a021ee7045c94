#pragma once

#include <assessment/safety_cases.h>
#include <parameters/scenario_parameters.h>
#include <uncertainty/reliability.h>
#include <uncertainty/sensitivity.h>
#include <uncertainty/surrogate.h>

#include <openturns/Distribution.hxx>

#include <iosfwd>
#include <string>
#include <vector>

namespace FloorBlock::Assessment
{
  /** @brief A model's share of the study's work. */
  struct ModelCost
  {
    std::string   model;       ///< "fem", "surrogate"
    std::uint64_t evaluations = 0;
    /** Of them, those an earlier run computed (FEM records reused). */
    std::uint64_t from_earlier_runs = 0;
    double        wall_time = 0.; ///< s, summed over the evaluations
  };

  /** @brief P(FS < 1) from a model, with what bounds it. */
  struct FailureEstimate
  {
    Uncertainty::FailureProbability monte_carlo; ///< with its 95 % interval
    /**
     * P(FS < 1 - e) and P(FS < 1 + e) for the surrogate's stated error e:
     * where P_f may lie if the surrogate errs by e near FS = 1.
     */
    double lower_with_surrogate_error = 0.;
    double upper_with_surrogate_error = 0.;
  };

  /** @brief Everything `assess` found. */
  struct AssessmentResult
  {
    std::vector<Parameters::UncertainInput>   inputs;
    std::vector<Parameters::InputCorrelation> correlations;
    std::vector<SafetyCase>                   training;
    std::vector<SafetyCase>                   validation;
    Uncertainty::Surrogate                    surrogate;
    Uncertainty::HeldOutErrors                held_out;
    FailureEstimate                           failure;
    Uncertainty::DesignPoint                  design_point;
    /** Of the surrogate over the inputs' marginals taken independent. */
    Uncertainty::SobolIndices sobol;
    std::vector<ModelCost>    costs;
    /** The surrogate's FS at every training and validation case. */
    std::vector<double> surrogate_at_training, surrogate_at_validation;
  };

  /** @brief The study ended early: what it had done by its time budget. */
  struct AssessmentIncomplete
  {
    unsigned int n_cases_done  = 0;
    unsigned int n_cases_total = 0;
  };

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
   * a polynomial chaos of the verdict's safety factor fitted on them; then
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
