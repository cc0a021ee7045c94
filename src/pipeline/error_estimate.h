#pragma once

#include <output/fem_error_estimate.h>
#include <pipeline/fem_pipeline.h>

#include <optional>

namespace FloorBlock::Pipeline
{
  /**
   * @brief The discretisation error of each FEM figure, estimated as the
   * difference to one solve on refined_scene() (rigid blocks: twice the
   * points per joint): per joint,
   * |coarse - fine| and its ratio to |fine| for the normal force, contact
   * length and the peak stresses.
   */
  Output::FemErrorEstimate
  refined_solve_error(const FemOutcome &coarse, const FemOutcome &fine);

  /**
   * @brief The error estimate of a converged @p coarse solve when the scene
   * asks for one (Solver/Error estimate): solves refined_scene() into
   * @p folder's refined/ and compares (refined_solve_error()). None when
   * not asked for or @p coarse did not converge.
   */
  std::optional<Output::FemErrorEstimate>
  estimate_error(const Parameters::ScenarioParameters &scene,
                 const FemOutcome                     &coarse,
                 const Output::ResultFolder           &folder);

  /**
   * @brief Level 1 of `converge`'s uniform ladder (uniform_level_scene:
   * every cell of the scene's mesh halved) and Model/Rigid points per
   * joint doubled.
   */
  Parameters::ScenarioParameters
  refined_scene(Parameters::ScenarioParameters scene);
} // namespace FloorBlock::Pipeline
