#pragma once

#include <parameters/scenario_parameters.h>
#include <rigid/model_description.h>

namespace FloorBlock::Scene
{
  /**
   * @brief The rigid-block model of a scene, built from the same inputs as
   * the contact FEM: the Gmsh assembly's geometry (assembly_description()),
   * and from floor_problem_settings() the density, gravity, joint constants
   * of the vertical joints and the bedding, uplift and load steps; the
   * support loads are the closed forms' P_i per metre (block_chain()), the
   * FEM's pressure P_i / L times L, vertical, at the block centre.
   *
   * Numerics: Model/Rigid points per joint; Solver/Newton tolerance, Max
   * Newton iterations and Max cutbacks as for the FEM; profiles of every
   * increment kept (the averaged peak along the lift needs them).
   * Ignored: corner rounding (the rigid model has sharp corners), the mesh
   * and the FEM's linear-solver settings.
   */
  RigidBlocks::ModelDescription
  rigid_model_description(const Parameters::ScenarioParameters &scene);

  /** @brief Whether the scene is solved with rigid blocks (Model/Blocks). */
  bool
  uses_rigid_blocks(const Parameters::ScenarioParameters &scene);
} // namespace FloorBlock::Scene
