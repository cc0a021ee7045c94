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
   * - alpha_i: the bedding's inclination under block i against the true
   *   horizontal, true_inclination() of the planar inclination or of the
   *   chord slope of block i on the parabola y = x^2/k
   *   (Analytic::parabolic_inclinations), both given in the frame.
   */
  Analytic::BlockChain
  block_chain(const Parameters::ScenarioParameters &scene);

  /**
   * @brief The chapter's alpha (rad) of a bedding inclined by
   * @p frame_inclination in a frame turned by Bedding/Frame dip
   * @p frame_dip: frame_inclination - frame_dip.
   *
   * Derivation. The chapter's alpha is measured against the true
   * horizontal, positive where the bedding rises away from the face (its
   * reaction then pushes the blocks toward the face). The frame's x runs
   * away from the face and is turned so that moving along +x goes down by
   * the dip delta: a direction at angle beta above the frame's x lies at
   * beta - delta above the true horizontal in the same vertical plane (a
   * rotation by -delta). A bedding rising by alpha_frame in the frame
   * therefore rises by alpha_frame - delta away from the face. A level bed
   * in a frame dipping 10 deg has alpha = -10 deg: it falls away from the
   * face, and the weight's down-dip part pulls the blocks off the face.
   * Weights and vertical support loads act along the true vertical in the
   * FEM (Fem::ElasticModel::down), as the chapter's W_i and P_i do, so
   * they enter the chain unchanged.
   */
  double
  true_inclination(double frame_inclination, double frame_dip);

  /**
   * @brief Floor lift y of Eq. 6.51 at the face joint (m), from the bedding
   * geometry: the differential lift across block n against the face block,
   * which stands upright in the frame (Analytic::joint_floor_lift of the
   * two true inclinations; the frame dip cancels).
   */
  double
  face_joint_floor_lift(const Parameters::ScenarioParameters &scene,
                        const Analytic::BlockChain           &chain);
} // namespace FloorBlock::Scene
