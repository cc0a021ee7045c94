#pragma once

#include <parameters/scenario_parameters.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /**
   * @brief report.md: the scene, a table per joint (FEM against each closed
   * form, contact area and stresses against 6.51-6.53), the plots, one
   * verdict per quantity, the error estimate and the cost.
   * @param[in] summary The summary.json content so far (analytic, fem,
   * comparison, fem_error_estimate).
   */
  std::string
  report_markdown(const Parameters::ScenarioParameters &scene,
                  const nlohmann::json &                summary,
                  const std::vector<std::string> &      verdicts);
} // namespace FloorBlock::Output
