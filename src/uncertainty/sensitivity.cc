#include <openturns/RandomGenerator.hxx>
#include <openturns/SaltelliSensitivityAlgorithm.hxx>
#include <openturns/SobolIndicesExperiment.hxx>
#include <uncertainty/sensitivity.h>

#include <stdexcept>

namespace FloorBlock::Uncertainty
{
  SobolIndices
  sobol_indices(const OT::Function     &model,
                const OT::Distribution &inputs,
                const std::uint64_t     base_size,
                const std::uint64_t     seed)
  {
    if (model.getInputDimension() != inputs.getDimension() ||
        model.getOutputDimension() != 1)
      throw std::invalid_argument(
        "uncertainty: the model must map the inputs' dimension (" +
        std::to_string(inputs.getDimension()) + ") to one value");
    if (!inputs.hasIndependentCopula())
      throw std::invalid_argument(
        "uncertainty: Sobol' indices need independent inputs");
    OT::RandomGenerator::SetSeed(seed);
    const OT::SobolIndicesExperiment       experiment(inputs, base_size);
    const OT::Sample                       input_sample = experiment.generate();
    const OT::Sample                       output_sample = model(input_sample);
    const OT::SaltelliSensitivityAlgorithm algorithm(input_sample,
                                                     output_sample,
                                                     base_size);
    return {algorithm.getFirstOrderIndices(),
            algorithm.getTotalOrderIndices(),
            algorithm.getFirstOrderIndicesInterval(),
            algorithm.getTotalOrderIndicesInterval(),
            input_sample.getSize()};
  }
} // namespace FloorBlock::Uncertainty
