#pragma once

#include <output/comparison_report.h>
#include <parameters/scenario_parameters.h>
#include <pipeline/fem_pipeline.h>
#include <scene/closed_forms.h>

namespace FloorBlock::Pipeline
{
  /**
   * @brief The FEM against the chapter's closed forms: every vertical joint
   * at the last converged increment, and the face joint at every converged
   * uplift increment (its lift = stage factor x Loading/Floor lift).
   * @pre @p outcome has at least one converged increment.
   */
  Output::RunComparison
  compare_with_closed_forms(const FemOutcome                     &outcome,
                            const Scene::ClosedForms             &closed_forms,
                            const Parameters::ScenarioParameters &scene);
} // namespace FloorBlock::Pipeline
