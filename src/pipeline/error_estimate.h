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
   * Estimated error of a figure per unit of its difference to the refined
   * solve: Richardson's r^p / (r^p - 1) for the coarse value with r = 2 and
   * p = 1, times Roache's safety factor 1.25, i.e. 2.5. p = 1 because a
   * contact end is located to first order at best (observed 0.6 on the
   * default scene's face contact length); the plain difference (p = inf)
   * did not bracket the finest level. Measured against the default scene's
   * nested level 3 (312k DoFs): face contact length true error 6.6 mm,
   * estimate 10.2 mm (the difference alone 4.1); averaged peak 0.29 MPa,
   * estimate 0.35 (difference 0.14); Q 2.1 kN/m, estimate 2.9; peak 0.18
   * MPa, estimate 0.26. Rigid law: contact 3.6 mm, estimate 8.8.
   */
  constexpr double error_from_refined_difference = 2. * 1.25;

  /**
   * @brief Level 1 of `converge`'s uniform ladder (uniform_level_scene:
   * every cell of the scene's mesh halved) and Model/Rigid points per
   * joint doubled.
   */
  Parameters::ScenarioParameters
  refined_scene(Parameters::ScenarioParameters scene);
} // namespace FloorBlock::Pipeline
