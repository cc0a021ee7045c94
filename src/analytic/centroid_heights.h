#pragma once

#include <analytic/block_chain.h>

#include <cstddef>
#include <vector>

namespace FloorBlock::Analytic
{
  /**
   * @brief Height of the lateral-force resultant on each joint and the
   * rotation criterion for the no-rotation mechanism.
   */
  struct CentroidHeights
  {
    Status status = Status::ok;
    /** Chapter number of the first offending block, 0 if none. */
    std::size_t failing_block = 0;
    /** h_i, height of Q_i above the base of block i (m). */
    std::vector<double> centroid_height;
    /** H - h_i (m); negative means block i rotates (criterion 6.21). */
    std::vector<double> rotation_margin;
    /** Chapter number of the first block with h_i > H, 0 if none. */
    std::size_t first_rotating_block = 0;
  };

  /**
   * @brief Heights h_i of the lateral forces of the no-rotation mechanism
   * (eqs. 6.14-6.20, 6.25) and the rotation criterion (replaces 6.21).
   *
   * Moments about the uphill base corner of block i, where the base
   * reaction acts in the no-rotation mechanism (6.14, 6.17 with the sign of
   * the Q_{i-1} h_{i-1} term corrected as 6.18 already has it):
   * \f[ Q_i h_i = Q_{i-1} h_{i-1} + \frac{W_i L}{2} + P_i\,r\,L
   *     + Q_i L \tan\phi_v, \f]
   * with r = BlockChain::support_load_position. For equal blocks, P = 0
   * and planar bedding this is eq. 6.20. This h_i is the highest point at
   * which Q_i can act without the block rotating into full base contact;
   * since Q_i cannot act above the block top, block i rotates when
   * \f$h_i > H\f$. The printed 6.21 is the moment balance of the same block
   * about its centre and therefore holds with equality (README.md).
   * Heights of neighbouring blocks are referred to each block's own base,
   * neglecting the offset L tan(alpha) between adjacent bases (chapter's
   * assumption, small for alpha L << H).
   *
   * @param[in] chain Inputs, SI units.
   * @param[in] lateral_force Q_1..Q_n (N/m) from slip_no_rotation().
   * @return h_i and H - h_i (m). Status joint_opens (empty vectors) if some
   * Q_i <= 0, invalid_input on bad inputs or a length mismatch.
   */
  CentroidHeights
  centroid_heights(const BlockChain          &chain,
                   const std::vector<double> &lateral_force);
} // namespace FloorBlock::Analytic
