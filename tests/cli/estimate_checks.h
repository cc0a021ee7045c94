#pragma once

// Checks of run's error estimates (summary.json's fem_error_estimate)
// against converged values, shared by the CLI and scenario tests.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace FloorBlockTest
{
  /** A figure's fem.json key and its converged value (SI). */
  using ConvergedFigure = std::pair<std::string, double>;

  /**
   * @brief Expects each figure of one joint's estimate (@p joint:
   * fem_error_estimate.joints["vertical n"]) to bracket its converged
   * value: |value - converged| <= absolute_error.
   */
  inline void
  expect_estimates_bracket(const nlohmann::json               &joint,
                           const std::vector<ConvergedFigure> &converged)
  {
    for (const auto &[figure, reference] : converged)
      {
        const double value = joint[figure]["value"].get<double>();
        const double error = joint[figure]["absolute_error"].get<double>();
        EXPECT_LE(std::abs(value - reference), error)
          << figure << ": value " << value << ", estimate " << error
          << ", converged " << reference;
      }
  }

  /**
   * Converged face joint of tests/scenarios/three_blocks.prm: `converge
   * --mode uniform --levels 5`, level 4 (226k DoFs): 684.17 mm, 3722.53
   * kN/m (levels 2-4: 683.65, 683.84, 684.17 mm).
   */
  inline const std::vector<ConvergedFigure> three_blocks_converged_face = {
    {"normal_force_N_per_m", 3.722527599e+06},
    {"contact_length_m", 6.841650920e-01}};
} // namespace FloorBlockTest
