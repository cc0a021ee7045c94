#pragma once

#include <output/fem_error_estimate.h>
#include <safety/corner_safety.h>
#include <scene/closed_forms.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /**
   * @brief summary.json's "floor_safety": the engineer's answer of `run`.
   * Per floor-level corner (Safety::corner_safety()) safety_factor_point,
   * safety_factor_line and safety_factor_area, each with its estimated
   * relative error
   * (FemErrorEstimate::corners; null where not estimated, the corner's
   * status saying why, else "estimated"); the governing corner; beside them the chapter's route,
   * safety_factor_eq_6_53 per mechanism (floor strength over Eq. 6.53's
   * sigma_max; absent where that has no answer) and floor_strength_Pa.
   * status: "holds", "fails" (by verdict_method, the line method with
   * compliant joints, the area method with exact contact;
   * Safety::verdict_factor()) or "unresolved" (with status_text), or
   * "not evaluated" where the FEM gave no corner stresses (3D, rigid
   * blocks, no converged increment).
   */
  nlohmann::json
  floor_safety_summary_json(const std::vector<Safety::CornerSafety> &corners,
                            const std::optional<FemErrorEstimate>   &estimate,
                            const Scene::ClosedForms &closed_forms);

  /** @brief `run`'s terminal lines of floor_safety_summary_json(). */
  std::string
  floor_safety_summary_lines(const std::vector<Safety::CornerSafety> &corners,
                             const std::optional<FemErrorEstimate> &estimate,
                             const Scene::ClosedForms &closed_forms);

  /** @brief report.md's section "Floor safety" (Markdown). */
  std::string
  floor_safety_markdown(const std::vector<Safety::CornerSafety> &corners,
                        const std::optional<FemErrorEstimate>   &estimate,
                        const Scene::ClosedForms                &closed_forms);
} // namespace FloorBlock::Output
