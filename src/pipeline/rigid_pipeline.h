#pragma once

#include <pipeline/fem_pipeline.h>

namespace FloorBlock::Pipeline
{
  /**
   * @brief solve_scene() for a scene with Model/Blocks = rigid: solves the
   * rigid-block model (Scene::rigid_model_description()), adapts its
   * results to the FEM's structures (RigidBlocks::to_contact_result()) and
   * writes fem.json and joints.csv with the FEM's writers.
   *
   * fem.json says "model": "rigid blocks" and lists under "absent" what the
   * rigid model does not produce (mesh, VTU files, contact node pairs), with
   * the reason; no mesh or VTU file is written. A failed solve
   * (floating_block, no_equilibrium, not_converged) is reported, not
   * thrown: status "not converged", the rigid status and its reason in
   * status_text, and the increments converged before it.
   */
  FemOutcome
  solve_rigid_scene(const Parameters::ScenarioParameters &scene,
                    const Output::ResultFolder           &folder);
} // namespace FloorBlock::Pipeline
