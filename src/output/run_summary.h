#pragma once

#include <contact/results.h>
#include <output/comparison_report.h>
#include <output/fem_error_estimate.h>
#include <output/fem_report.h>
#include <parameters/scenario_parameters.h>
#include <scene/closed_forms.h>

#include <nlohmann/json.hpp>

#include <optional>

namespace FloorBlock::Output
{
  /**
   * @brief `run`'s summary.json: scene, model, inputs, the closed forms
   * (analytic.json), fem.json, the error estimate, the face joint's figures,
   * the floor's safety factors (floor_safety_summary_json()),
   * the comparison with the closed forms, status and the total wall time.
   * The estimate, figures and comparison are left out where absent (no
   * converged increment, no estimate asked for).
   * @param[in] wall_time Of the whole run (s).
   */
  nlohmann::json
  run_summary_json(const Parameters::ScenarioParameters  &scene,
                   const Scene::ClosedForms              &closed_forms,
                   const Contact::SolveResult            &result,
                   const FemReport                       &report,
                   const std::optional<FemErrorEstimate> &estimate,
                   const std::optional<RunComparison>    &comparison,
                   const double                           wall_time);
} // namespace FloorBlock::Output
