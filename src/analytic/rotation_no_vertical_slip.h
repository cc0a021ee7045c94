#pragma once

#include <analytic/block_chain.h>

namespace FloorBlock::Analytic
{
  /**
   * @brief Blocks rotated into full contact with the bedding, slipping on
   * it, with no slip along the vertical joints; planar (section 6.4.5,
   * eqs. 6.26-6.28) and curved bedding (section 6.4.6, eqs. 6.29-6.38).
   *
   * One function covers both: the printed planar form 6.26-6.28 is
   * dimensionally inconsistent and one global moment equation cannot give
   * the n base forces (README.md), so the planar case is the curved
   * recursion with all alpha_i equal.
   *
   * Q_i is parallel to the bedding of block i and acts at the top corners
   * (floor level); N_i acts at the uphill base corner. Moments about the
   * face-side top corner, then bed-parallel and bed-normal equilibrium of
   * block i (frame of block i, see Internal::force_from_away_neighbour
   * for the incoming \f$\tilde Q_{i-1}, \tilde V_{i-1}\f$):
   * \f[ N_i = \frac{M_i - L\tilde V_{i-1}}{L - H\tan\phi_h},\quad
   *     Q_i = \tilde Q_{i-1} + N_i\tan\phi_h + (W_i+P_i)\sin\alpha_i,\quad
   *     V_i = N_i + \tilde V_{i-1} - (W_i+P_i)\cos\alpha_i, \f]
   * with \f$M_i = W_i(L\cos\alpha_i + H\sin\alpha_i)/2 +
   * P_i(1-r)L\cos\alpha_i\f$. For alpha -> 0 this is the chapter's
   * 6.29-6.38, which drops the (W+P) sin(alpha) term and the sin(Delta)
   * coupling and misprints 6.32 (V_1 = N_1 - W_1 - P_1).
   *
   * @param[in] chain Inputs, per metre of face, SI units.
   * @return Q_i, N_i, V_i (N/m), offset 0 (N_i at the uphill corner).
   * Status rotation_denominator_nonpositive (empty vectors) if
   * \f$L \le H\tan\phi_h\f$; vertical_friction_exceeded (values kept) if
   * \f$|V_i| > Q_i\tan\phi_v\f$; joint_opens / base_lifts_off for
   * tension; invalid_input for bad inputs.
   */
  ChainForces
  rotation_no_vertical_slip(const BlockChain &chain);
} // namespace FloorBlock::Analytic
