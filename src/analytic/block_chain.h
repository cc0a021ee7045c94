#pragma once

#include <analytic/status.h>

#include <cstddef>
#include <vector>

namespace FloorBlock::Analytic
{
  /**
   * @brief Inputs of the multiple sliding block model (chapter 6, Fig. 6.3),
   * per metre of face, SI units.
   *
   * Numbering follows the chapter: index 0 is block 1 at the free end of
   * the chain, index n-1 is block n next to the fixed face block. Joint i
   * lies between block i and block i+1; joint n is the contact with the
   * face block, and lateral_force[n-1] = Q_n is the thrust on the face.
   *
   * Sign convention (the chapter's): inclination alpha_i > 0 when the
   * bedding under block i rises away from the face, so the bedding
   * reaction pushes the blocks towards the face, which resists with Q.
   */
  struct BlockChain
  {
    /** W_i, block self weight per metre of face (N/m), >= 0. */
    std::vector<double> weight;
    /** P_i, vertical powered-support load per metre of face (N/m), >= 0. */
    std::vector<double> support_load;
    /** alpha_i, bedding dip under block i (rad), in (-pi/2, pi/2). */
    std::vector<double> inclination;
    /** L, block width perpendicular to the face (m), > 0. */
    double block_width = 0.;
    /** H, block height from bedding to floor level (m), > 0. */
    double block_height = 0.;
    /** phi_h, friction angle of the failed bedding plane (rad). */
    double bedding_friction = 0.;
    /** phi_v, friction angle of the vertical fractures (rad). */
    double vertical_friction = 0.;
    /**
     * Where the resultant of P_i acts on the block top, as a fraction of
     * L measured from the uphill (away-from-face) edge: 0.5 for a uniform
     * support pressure (default), 1 for the face-side edge, which is what
     * the printed eq. 6.25 implies. Only moments (6.15-6.21, 6.25 and the
     * rotation cases) depend on it.
     */
    double support_load_position = 0.5;

    /** @brief Number of blocks n. */
    std::size_t
    n_blocks() const;
  };

  /**
   * @brief Forces along the chain for one mechanism. All per metre of face
   * (N/m); to get the force over a support of width b multiply by b.
   *
   * When status says a denominator vanished, the vectors are empty. When
   * the answer is finite but the mechanism is inadmissible, the values are
   * kept and failing_block names the first offending block.
   */
  struct ChainForces
  {
    Status status = Status::ok;
    /** Chapter (1-based) number of the first offending block, 0 if none. */
    std::size_t failing_block = 0;
    /** Q_i on joint i (N/m); the last entry is the thrust on the face. */
    std::vector<double> lateral_force;
    /** N_i, base normal force of block i (N/m). */
    std::vector<double> normal_force;
    /**
     * V_i, shear on joint i, positive when block i+1 pushes block i
     * towards the bedding (N/m). Equals Q_i tan(phi_v) where joints slip.
     */
    std::vector<double> joint_shear;
    /**
     * Distance of the base normal force N_i from the uphill base corner
     * of block i (m); 0 means N_i acts at that corner.
     */
    std::vector<double> normal_force_offset;
  };

  /**
   * @brief Check a chain for finite, in-range inputs and equal vector
   * lengths.
   * @return Status::ok or Status::invalid_input.
   */
  Status
  validate(const BlockChain &chain);

  /**
   * @brief A chain of n identical blocks on one inclination (the chapter's
   * planar case, eq. 6.9/6.23).
   * @param[in] n_blocks n >= 1.
   * @param[in] weight W (N/m); @param[in] support_load P (N/m) on every block.
   * @param[in] inclination alpha (rad).
   * @param[in] block_width L (m); @param[in] block_height H (m).
   * @param[in] bedding_friction phi_h (rad);
   * @param[in] vertical_friction phi_v (rad).
   */
  BlockChain
  uniform_chain(const std::size_t n_blocks,
                const double      weight,
                const double      support_load,
                const double      inclination,
                const double      block_width,
                const double      block_height,
                const double      bedding_friction,
                const double      vertical_friction);
} // namespace FloorBlock::Analytic
