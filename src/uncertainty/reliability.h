#pragma once

#include <openturns/Distribution.hxx>
#include <openturns/Function.hxx>
#include <openturns/Point.hxx>

#include <cstdint>

namespace FloorBlock::Uncertainty
{
  /**
   * @brief When a Monte Carlo estimate of P(FS < 1) may stop: once its 95 %
   * confidence interval is at most 2 half_width wide, or after
   * max_evaluations evaluations of the model, whichever comes first.
   */
  struct SimulationSettings
  {
    double        half_width      = 0.02;   ///< of the 95 % interval (-)
    std::uint64_t max_evaluations = 100000; ///< of the safety factor
    std::uint64_t block_size      = 100;    ///< evaluations per batch
    std::uint64_t seed            = 0;      ///< of the random generator
  };

  /** @brief A failure probability with its 95 % confidence interval. */
  struct FailureProbability
  {
    double        probability = 0.; ///< P(FS < 1) (-)
    double        half_width  = 0.; ///< of its 95 % confidence interval (-)
    std::uint64_t evaluations = 0;  ///< of the safety factor
  };

  /**
   * @brief P(FS < 1) by Monte Carlo (OpenTURNS'
   * ProbabilitySimulationAlgorithm over a MonteCarloExperiment): samples
   * of @p inputs through @p safety_factor, until @p settings says stop.
   * @param[in] safety_factor An OpenTURNS function from the inputs'
   *   dimension to one output, FS.
   * @throws std::invalid_argument if the dimensions do not match.
   */
  FailureProbability
  monte_carlo_failure_probability(const OT::Function       &safety_factor,
                                  const OT::Distribution   &inputs,
                                  const SimulationSettings &settings);

  /** @brief The first-order reliability method's answer. */
  struct DesignPoint
  {
    double    reliability_index = 0.; ///< beta, the generalised index (-)
    double    probability       = 0.; ///< Phi(-beta) (-)
    OT::Point point; ///< the most probable failure point, in the inputs' units
  };

  /**
   * @brief FORM for FS < 1: the point of the failure domain nearest the
   * origin of the standard space (Cobyla, from the inputs' mean), beta and
   * the first-order P(FS < 1). Exact for a safety factor that is linear in
   * normal inputs; elsewhere an approximation that the Monte Carlo
   * estimate checks.
   * @throws std::invalid_argument if the dimensions do not match.
   */
  DesignPoint
  form_design_point(const OT::Function     &safety_factor,
                    const OT::Distribution &inputs);
} // namespace FloorBlock::Uncertainty
