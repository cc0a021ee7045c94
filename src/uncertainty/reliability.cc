#include <openturns/Cobyla.hxx>
#include <openturns/CompositeRandomVector.hxx>
#include <openturns/FORM.hxx>
#include <openturns/Less.hxx>
#include <openturns/MonteCarloExperiment.hxx>
#include <openturns/ProbabilitySimulationAlgorithm.hxx>
#include <openturns/RandomGenerator.hxx>
#include <openturns/ThresholdEvent.hxx>
#include <uncertainty/reliability.h>

#include <stdexcept>

namespace FloorBlock::Uncertainty
{
  namespace
  {
    /** The event FS < 1 of @p safety_factor over @p inputs. */
    OT::ThresholdEvent
    failure_event(const OT::Function     &safety_factor,
                  const OT::Distribution &inputs)
    {
      if (safety_factor.getInputDimension() != inputs.getDimension() ||
          safety_factor.getOutputDimension() != 1)
        throw std::invalid_argument(
          "uncertainty: the safety factor must map the inputs' dimension (" +
          std::to_string(inputs.getDimension()) + ") to one value");
      const OT::CompositeRandomVector factor(safety_factor,
                                             OT::RandomVector(inputs));
      return OT::ThresholdEvent(factor, OT::Less(), 1.);
    }
  } // namespace

  FailureProbability
  monte_carlo_failure_probability(const OT::Function       &safety_factor,
                                  const OT::Distribution   &inputs,
                                  const SimulationSettings &settings)
  {
    const OT::ThresholdEvent event = failure_event(safety_factor, inputs);
    OT::RandomGenerator::SetSeed(settings.seed);
    OT::ProbabilitySimulationAlgorithm algorithm(event,
                                                 OT::MonteCarloExperiment());
    algorithm.setBlockSize(settings.block_size);
    algorithm.setMaximumOuterSampling(
      (settings.max_evaluations + settings.block_size - 1) /
      settings.block_size);
    // The 95 % interval is +- 1.96 standard deviations of the estimate.
    algorithm.setMaximumCoefficientOfVariation(-1.);
    algorithm.setMaximumStandardDeviation(settings.half_width / 1.96);
    algorithm.run();
    const OT::ProbabilitySimulationResult result = algorithm.getResult();
    return {result.getProbabilityEstimate(),
            0.5 * result.getConfidenceLength(0.95),
            result.getOuterSampling() * result.getBlockSize()};
  }

  DesignPoint
  form_design_point(const OT::Function     &safety_factor,
                    const OT::Distribution &inputs)
  {
    const OT::ThresholdEvent event = failure_event(safety_factor, inputs);
    // Converged to the digits of P_f (the defaults stop at about 1e-5 of
    // beta; a design point is cheap next to the Monte Carlo estimate).
    OT::Cobyla solver;
    solver.setMaximumEvaluationNumber(10000);
    solver.setMaximumAbsoluteError(1e-10);
    solver.setMaximumRelativeError(1e-10);
    solver.setMaximumResidualError(1e-10);
    solver.setMaximumConstraintError(1e-10);
    OT::FORM form(solver, event, inputs.getMean());
    form.run();
    const OT::FORMResult result = form.getResult();
    return {result.getGeneralisedReliabilityIndex(),
            result.getEventProbability(),
            result.getPhysicalSpaceDesignPoint()};
  }
} // namespace FloorBlock::Uncertainty
