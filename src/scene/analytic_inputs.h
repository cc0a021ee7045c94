#pragma once

#include <analytic/block_chain.h>
#include <parameters/scenario_parameters.h>

#include <vector>

namespace FloorBlock::Scene
{
  /**
   * @brief The block chain of a scene, per metre of face, in the chapter's
   * numbering (index 0 = block 1 at the free end).
   *
   * - W_i = rho g L H: with vertical sides and a base on the bedding, a block
   *   lies between two curves a vertical distance H apart, so its area is
   *   L H on any bedding shape.
   * - P_i = F / (n_loaded b) on each loaded block: the support's total load F
   *   spread evenly over the loaded blocks and over the support width b.
   * - alpha_i: the planar inclination, or the chord slope of block i on the
   *   parabola y = x^2/k (Analytic::parabolic_inclinations).
   */
  Analytic::BlockChain
  block_chain(const Parameters::ScenarioParameters &scene);

  /**
   * @brief Floor lift y of Eq. 6.51 at the face joint (m), from the bedding
   * geometry: the differential lift across block n against the upright face
   * block (Analytic::joint_floor_lift).
   */
  double
  face_joint_floor_lift(const Parameters::ScenarioParameters &scene,
                        const Analytic::BlockChain           &chain);
} // namespace FloorBlock::Scene
