#pragma once

#include <analytic/block_chain.h>

#include <cstddef>

namespace FloorBlock::Analytic
{
  namespace Internal
  {
    /**
     * @brief A joint force in the frame of a rotated block: `along` the
     * bedding (positive away from the face), `normal` to it (positive
     * away from the bedding). Both N/m.
     */
    struct FrameForce
    {
      double along  = 0.;
      double normal = 0.;
    };

    /**
     * @brief The force that block i-1 (away side) exerts on block i, in
     * block i's frame, for the rotation mechanisms 6.29-6.46.
     *
     * Joint forces are stored in the frame of the block on the away side
     * of the joint: block i-1 receives +Q along and -V normal from block
     * i. Block i receives the opposite vector, rotated by
     * \f$\Delta = \alpha_{i-1} - \alpha_i\f$:
     * \f[ \tilde Q = Q\cos\Delta + V\sin\Delta,\quad
     *     \tilde V = V\cos\Delta - Q\sin\Delta \f]
     * (returned as along = -Q~, normal = +V~). The chapter keeps only the
     * cos(Delta) factors (6.31, 6.33-6.38) and drops the sin(Delta) terms.
     * @param[in] block 0-based index of the receiving block, >= 1.
     */
    FrameForce
    force_from_away_neighbour(const BlockChain &chain,
                              const std::size_t block,
                              const double      lateral_force,
                              const double      joint_shear);

    /**
     * @brief Moment of W_i and P_i about the face-side top corner of the
     * rotated block i, clockwise positive (N m / m):
     * \f$W(L\cos\alpha + H\sin\alpha)/2 + P (1-r) L \cos\alpha\f$.
     */
    double
    load_moment_about_top_corner(const BlockChain &chain,
                                 const std::size_t block);
  } // namespace Internal
} // namespace FloorBlock::Analytic
