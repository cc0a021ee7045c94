#pragma once

#include <vector>

namespace FloorBlock::Solver
{
  /**
   * @brief The near-null space that smoothed-aggregation AMG (ML) builds
   * its coarse spaces from: the motions the operator barely resists.
   *
   * For elasticity these are the rigid-body modes, translations and
   * rotations (3 in 2D, 6 in 3D); ML restricts them to each aggregate, so
   * one global set serves every body of a block assembly. A header of
   * plain data: the FE space fills it (Fem::rigid_body_modes), the solver
   * hands it to ML, and neither knows the other.
   */
  struct NearNullSpace
  {
    /** Unknowns per mesh node, numbered together (ML's "PDE equations"). */
    unsigned int n_components = 1;
    /**
     * modes[k][i]: mode k at the i-th locally owned unknown, in the order
     * of the locally owned index set (the matrix's row order).
     */
    std::vector<std::vector<double>> modes;
  };
} // namespace FloorBlock::Solver
