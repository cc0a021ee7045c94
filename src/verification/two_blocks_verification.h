#pragma once

#include <contact/contact_problem.h>
#include <verification/verification_setup.h>

namespace FloorBlock::Verification
{
  /** @brief Settings of the two-blocks verification. */
  struct TwoBlocksSettings
  {
    /** Cells per metre of the structured meshes (blocks 1 m x 2 m). */
    unsigned int          cells_per_metre = 4;
    Contact::JointLawKind law             = Contact::JointLawKind::compliant;
    double joint_stiffness  = 9e9; ///< kn = ks, compliant law (Pa/m)
    double lateral_pressure = 4e5; ///< on the upper quarter (Pa)
    /**
     * Local refinements (hanging nodes) of the cells within
     * corner_refinement_radius of the joint's top corner, on both sides
     * alike so that the joint sides still match node by node.
     */
    unsigned int corner_refinements       = 0;
    double       corner_refinement_radius = 0.6; ///< m
  };

  /**
   * Relative tolerance of the joint normal force against the applied
   * lateral force: horizontal equilibrium of the right block on its
   * frictionless bedding, exact in any discretisation, so only round-off
   * and the Newton tolerance remain.
   */
  constexpr double two_blocks_tolerance = equilibrium_tolerance;

  /** @brief Joint and block response of the two-blocks case. */
  struct TwoBlocksResult
  {
    /** Closed form: the applied lateral force per metre (N/m). */
    double applied_lateral_force = 0.;
    double joint_normal_force    = 0.; ///< N/m
    double closed_length         = 0.; ///< m
    double averaged_peak         = 0.; ///< Pa
    double right_rotation        = 0.; ///< rad
    double relative_imbalance    = 0.;
    double block_height          = 0.; ///< m
  };

  /**
   * @brief A fixed left block and a free right block (1 m x 2 m, table
   * rock, own weight) on a frictionless bedding over an elastic base; a
   * lateral pressure on the upper quarter of the right block's outer side
   * pushes it against the left one. Horizontal equilibrium of the right
   * block: the vertical joint's normal force equals the applied lateral
   * force; the block tilts, so the joint closes only over its upper part.
   */
  TwoBlocksResult
  run_two_blocks_verification(const TwoBlocksSettings &settings);
} // namespace FloorBlock::Verification
