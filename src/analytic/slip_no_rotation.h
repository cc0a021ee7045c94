#pragma once

#include <analytic/block_chain.h>

namespace FloorBlock::Analytic
{
  /**
   * @brief Slip along the bedding and all vertical fractures, no block
   * rotation (chapter section 6.4.1 and 6.4.3; eqs. 6.1-6.13, 6.22-6.24).
   *
   * The blocks stay upright and touch the inclined bedding at their uphill
   * base corner; Q_i is horizontal (normal to the vertical joint) and the
   * joint friction Q_i tan(phi_v) acts downwards on block i. With
   * \f$a_i = \sin\alpha_i + \tan\phi_h\cos\alpha_i\f$ and
   * \f$c_i = \sin\alpha_i + \tan\phi_v\cos\alpha_i\f$, horizontal and
   * bed-normal equilibrium of block i give the recursion
   * \f[ Q_i = Q_{i-1} + \frac{(W_i+P_i)\cos\alpha_i\,a_i}{1 - a_i c_i},
   * \qquad N_i = (W_i+P_i)\cos\alpha_i + (Q_i - Q_{i-1})c_i, \f]
   * which is eq. 6.12 in general and eq. 6.8/6.9/6.23 for a planar bed.
   * The printed 6.13/6.24 sum the Q_i themselves; see README.md.
   *
   * Validity: rigid blocks, cohesionless Coulomb joints at limit
   * equilibrium in every joint, no rotation (check centroid_heights()).
   *
   * @param[in] chain Inputs, per metre of face, SI units.
   * @return Q_i, N_i (N/m), V_i = Q_i tan(phi_v) (N/m), normal force
   * offset 0 (uphill corner). Status self_locking (empty vectors) if
   * \f$1 - a_i c_i \le 0\f$ for some block, joint_opens or base_lifts_off
   * if a block on a bed dipping towards the face (alpha_i < -phi_h) would
   * pull its neighbours, invalid_input for bad inputs.
   */
  ChainForces
  slip_no_rotation(const BlockChain &chain);
} // namespace FloorBlock::Analytic
