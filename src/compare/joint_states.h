#pragma once

#include <contact/results.h>
#include <scene/closed_forms.h>

#include <string>
#include <vector>

namespace FloorBlock::Compare
{
  /**
   * How far along its Coulomb limit the FEM carries each joint, and which of
   * the chapter's mechanisms assume those joint states. The mechanisms
   * differ in what they assume of the joints: no_rotation and
   * rotation_vertical_slip let every vertical joint and every bed slip,
   * rotation_no_vertical_slip lets the beds slip with the vertical joints
   * stuck. Only a mechanism whose assumptions the FEM's joints meet can be
   * expected to give the FEM's forces.
   */
  struct JointStates
  {
    /**
     * |V_j| / (N_j tan phi_v) of every vertical joint j = 1..n, then
     * |V_i| / (N_i tan phi_h) of every bed i = 1..n; 0 where N <= 0 (the
     * joint is open). 1 is the friction limit (no cohesion, as in the
     * chapter).
     */
    std::vector<double> vertical_use, bedding_use;
    /** Beds i (chapter numbering) that carry no normal force. */
    std::vector<unsigned int> open_beds;
    /**
     * Per vertical joint j: whether joints 1..j and the beds under blocks
     * 1..j are all at their limit, so the slip mechanisms' chain holds up
     * to joint j and their Q_j is the FEM's answer there.
     */
    std::vector<bool> slip_chain_holds;
    /** The mechanisms whose joint assumptions the FEM's joints meet. */
    std::vector<Scene::Mechanism> holding;
    /** The FEM's joint states in words. */
    std::string text;
  };

  /** A joint at or past this fraction of its limit counts as slipping. */
  constexpr double at_friction_limit = 1. - 1e-6;

  /**
   * @brief The joint states of @p increment against the friction angles of
   * @p closed_forms' chain.
   */
  JointStates
  joint_states(const Contact::IncrementResult &increment,
               const Scene::ClosedForms       &closed_forms);
} // namespace FloorBlock::Compare
