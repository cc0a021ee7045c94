#pragma once

#include <analytic/block_chain.h>

namespace FloorBlock::Analytic
{
  /**
   * @brief Blocks rotated into full contact with the bedding, slipping on
   * the bedding and on every vertical joint (section 6.4.7, eqs.
   * 6.39-6.46).
   *
   * Joint shear is at its friction limit, V_i = Q_i tan(phi_v); Q_i is
   * parallel to the bedding of block i. Bed-normal and bed-parallel
   * equilibrium of block i (frame of block i, incoming
   * \f$\tilde Q_{i-1}, \tilde V_{i-1}\f$ from
   * Internal::force_from_away_neighbour):
   * \f[ Q_i(1 - \tan\phi_h\tan\phi_v) = \tilde Q_{i-1}
   *     - \tan\phi_h\tilde V_{i-1}
   *     + (W_i+P_i)(\sin\alpha_i + \tan\phi_h\cos\alpha_i), \f]
   * \f[ N_i = (W_i+P_i)\cos\alpha_i + Q_i\tan\phi_v - \tilde V_{i-1}. \f]
   * Without the relative rotation of neighbours (\f$\tilde Q = Q\f$,
   * \f$\tilde V = Q\tan\phi_v\f$) this is the chapter's 6.44/6.46, whose
   * sum is correct here because each term is an increment.
   * The moment about the face-side top corner (Q at the top corners)
   * places N_i; it must lie on the base.
   *
   * @param[in] chain Inputs, per metre of face, SI units.
   * @return Q_i, N_i, V_i (N/m) and the distance of N_i from the uphill
   * base corner (m). Status self_locking (empty vectors) if
   * \f$\tan\phi_h\tan\phi_v \ge 1\f$; normal_force_outside_base (values
   * kept) if that distance leaves [0, L]; joint_opens / base_lifts_off for
   * tension; invalid_input for bad inputs.
   */
  ChainForces
  rotation_vertical_slip(const BlockChain &chain);
} // namespace FloorBlock::Analytic
