#pragma once

#include <app/fem_pipeline.h>

#include <nlohmann/json.hpp>

namespace FloorBlock::App
{
  /**
   * @brief The discretisation error of each FEM figure, estimated as the
   * difference to one solve with halved element sizes (until a refinement
   * ladder exists; rigid blocks: twice the points per joint): per joint,
   * |coarse - fine| and its ratio to |fine| for the normal force, contact
   * length and the peak stresses.
   */
  nlohmann::json
  refined_solve_error(const FemOutcome &coarse, const FemOutcome &fine);

  /**
   * @brief The scene with Mesh/Corner size and Mesh/Far size halved and
   * Model/Rigid points per joint doubled.
   */
  Parameters::ScenarioParameters
  refined_scene(Parameters::ScenarioParameters scene);
} // namespace FloorBlock::App
