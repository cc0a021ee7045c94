#pragma once

#include <scene/closed_forms.h>

#include <contact/results.h>
#include <output/comparison_report.h>
#include <output/fem_error_estimate.h>
#include <output/fem_report.h>
#include <parameters/scenario_parameters.h>

#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /**
   * @brief report.md: the scene, a table per joint (FEM against each closed
   * form, contact area and stresses against 6.51-6.53), the plots, one
   * verdict per quantity, the error estimate and the cost.
   * @param[in] result, report The solve and its FEM report.
   * @param[in] error_estimate The error estimate, if one was made.
   * @param[in] comparison The FEM against the closed forms.
   * @param[in] closed_forms The closed forms (the chapter's route to the
   *   floor's safety factor, beside the FEM's corner factors).
   */
  std::string
  report_markdown(const Parameters::ScenarioParameters  &scene,
                  const Contact::SolveResult            &result,
                  const FemReport                       &report,
                  const std::optional<FemErrorEstimate> &error_estimate,
                  const RunComparison                   &comparison,
                  const std::vector<std::string>        &verdicts,
                  const Scene::ClosedForms              &closed_forms);
} // namespace FloorBlock::Output
