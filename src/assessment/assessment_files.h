#pragma once

#include <assessment/assessment.h>
#include <nlohmann/json.hpp>

#include <string>

namespace FloorBlock::Assessment
{
  /**
   * @brief assess.json: P(FS < 1) with its 95 % interval and the range the
   * surrogate's error allows, FORM's beta and design point, first-order
   * and total Sobol' indices with intervals, the surrogate and its
   * errors, the cases by status and the cost by model.
   */
  nlohmann::json
  assessment_json(const AssessmentResult &result);

  /**
   * @brief cases.csv: one row per FEM case (training and held out), its
   * inputs in their parameters' units, the model that answered, its
   * status, the FEM's factors and the surrogate's FS at the same inputs.
   */
  std::string
  cases_csv(const AssessmentResult &result);

  /**
   * @brief design_limit.csv: P(FS < 1) with its 95 % half-width at each
   * value of the design limit input (result.design_limit must be set).
   */
  std::string
  design_limit_csv(const AssessmentResult &result);

  /** @brief A column name for an input: its path with its unit,
   * "Joints/Bedding friction angle (degrees)". */
  std::string
  input_column(const Parameters::UncertainInput &input);
} // namespace FloorBlock::Assessment
