#pragma once

#include <scene/closed_forms.h>

#include <nlohmann/json.hpp>

#include <string>

namespace FloorBlock::Output
{
  /**
   * @brief analytic.json content: per mechanism its status, Q_i per metre and
   * over b, N_i, V_i, and the corner contact (6.51-6.53) at the face joint.
   * Units are in the key names; failed mechanisms carry empty lists and a
   * status with its explanation, never NaN.
   */
  nlohmann::json
  analytic_json(const Scene::ClosedForms &closed_forms);

  /** @brief analytic.csv: one row per block, one column group per mechanism. */
  std::string
  analytic_csv(const Scene::ClosedForms &closed_forms);

  /** @brief The readable table printed by `floorblock analytic` (kN, MPa). */
  std::string
  analytic_table(const Scene::ClosedForms &closed_forms);
} // namespace FloorBlock::Output
