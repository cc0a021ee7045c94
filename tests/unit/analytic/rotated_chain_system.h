#pragma once

#include <analytic/block_chain.h>

#include <vector>

namespace FloorBlock::AnalyticTest
{
  /**
   * Independent equilibrium of a chain of rotated blocks (base in full
   * contact with the bedding, joint forces at the top corners), written in
   * global coordinates with explicit corner positions.
   */
  struct RotatedChainSolution
  {
    std::vector<double> lateral_force;
    std::vector<double> joint_shear;
    std::vector<double> normal_force;
    /** Distance of N_i from the uphill base corner (m). */
    std::vector<double> normal_force_offset;
  };

  /**
   * No vertical slip: unknowns Q_i, V_i, N_i; x, y and moment balance of
   * each block about its uphill base corner, where N_i is assumed.
   */
  RotatedChainSolution
  solve_rotated_chain_without_joint_slip(const Analytic::BlockChain &chain);

  /**
   * Slip on the vertical joints (V_i = Q_i tan phi_v): unknowns Q_i, N_i
   * from x and y balance; the position of N_i then from the moment about
   * the face-side base corner.
   */
  RotatedChainSolution
  solve_rotated_chain_with_joint_slip(const Analytic::BlockChain &chain);
} // namespace FloorBlock::AnalyticTest
