#pragma once

#include <parameters/uncertain_inputs.h>

#include <openturns/Distribution.hxx>

#include <vector>

namespace FloorBlock::Uncertainty
{
  /**
   * @brief The joint distribution of the uncertain inputs: each input's
   * marginal (Parameters::UncertainInput, in the parameter's own units,
   * described by its path) joined by a Gaussian copula with the given
   * correlations (others 0), or by the independent copula when there are
   * none.
   * @throws InputError naming Uncertainty/Correlations if the correlation
   *   matrix is not positive definite (e.g. three inputs pairwise at 0.9,
   *   -0.9 and 0.9).
   */
  OT::Distribution
  input_distribution(
    const std::vector<Parameters::UncertainInput>   &inputs,
    const std::vector<Parameters::InputCorrelation> &correlations);

  /** @brief One input's marginal distribution, as input_distribution() uses
   * it. */
  OT::Distribution
  marginal_distribution(const Parameters::UncertainInput &input);
} // namespace FloorBlock::Uncertainty
