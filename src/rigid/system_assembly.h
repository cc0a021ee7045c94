#pragma once

#include <rigid/block_loads.h>
#include <rigid/dense_system.h>
#include <rigid/joint_set.h>

#include <vector>

namespace FloorBlock::RigidBlocks
{
  /**
   * @brief Where assemble_system() accumulates: any target may be null.
   * Block i (index i - 1) owns rows 3(i-1) .. 3(i-1)+2 = (F_x, F_y, M).
   */
  struct AssemblyTargets
  {
    /** Residual R = f_int - f_ext (N/m; moment rows N m/m). */
    std::vector<double> *residual = nullptr;
    /** dR/dq, with q = (u_x, u_y, theta) per block. */
    DenseMatrix *tangent = nullptr;
    /**
     * Fraction of ks added as shear stiffness to the tangent of slipping
     * points (-); 0 = the consistent tangent. Only the search direction
     * changes, never the residual, so a converged answer is the same.
     */
    double slip_stabilisation = 0.;
  };

  /**
   * @brief The one assembly loop of the rigid-block model: joint forces of
   * every integration point (trapezoid weight times the law's force
   * density) projected on the block DOFs, minus the applied loads.
   *
   * The law's force density f is the internal force per length on side B
   * and -f on side A; with the jump \f$[u] = \Phi_B q_B - \Phi_A q_A\f$ the
   * tangent blocks are \f$\pm w\,\Phi^T (\partial f/\partial[u]) \Phi\f$.
   * Fixed sides (face block, base) have no rows.
   *
   * @param[in] joint_set Joints and centroids.
   * @param[in] responses Law responses at the current iterate.
   * @param[in] loads Block loads; @param[in] gravity_factor,
   *   @param[in] support_factor their current factors (-).
   * @param[out] targets Residual and/or tangent (overwritten).
   */
  void
  assemble_system(const JointSet                &joint_set,
                  const JointResponses          &responses,
                  const std::vector<BlockLoads> &loads,
                  const double                   gravity_factor,
                  const double                   support_factor,
                  const AssemblyTargets         &targets);
} // namespace FloorBlock::RigidBlocks
