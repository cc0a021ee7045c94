#pragma once

#include <openturns/Distribution.hxx>
#include <openturns/Function.hxx>
#include <openturns/Interval.hxx>
#include <openturns/Point.hxx>

#include <cstdint>

namespace FloorBlock::Uncertainty
{
  /** @brief First-order and total Sobol' indices with 95 % intervals. */
  struct SobolIndices
  {
    OT::Point     first_order; ///< per input (-)
    OT::Point     total_order; ///< per input (-)
    OT::Interval  first_order_interval;
    OT::Interval  total_order_interval;
    std::uint64_t evaluations = 0; ///< of the model
  };

  /**
   * @brief Sobol' indices of @p model's one output over independent
   * @p inputs: Saltelli's pick-freeze estimators (OpenTURNS'
   * SaltelliSensitivityAlgorithm) on a SobolIndicesExperiment of
   * @p base_size points, (d + 2) base_size evaluations, with bootstrap
   * 95 % intervals.
   * @throws std::invalid_argument if the dimensions do not match or
   *   @p inputs has a dependent copula (the indices assume independence).
   */
  SobolIndices
  sobol_indices(const OT::Function     &model,
                const OT::Distribution &inputs,
                std::uint64_t           base_size,
                std::uint64_t           seed);
} // namespace FloorBlock::Uncertainty
