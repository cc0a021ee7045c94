#pragma once

#include <contact/contact_node.h>

#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief Removes the redundant exact-law pairs at crosspoints, where a
   * node lies on two joints (a sharp block corner on the bedding, or a
   * corner held by a support), and gives each removed pair's weight to
   * the nearest remaining pair of its joint.
   *
   * Why: at the corner of two blocks on a base, three coincident nodes
   * form three pairs (the vertical joint and two bedding pairs). Closed
   * and stuck, their six constraints act on two relative displacements
   * and have rank four: the slip of the vertical pair is the difference
   * of the two bedding gaps, and its gap the difference of their slips.
   * Penalty springs do not mind; exact multipliers make the Newton matrix
   * singular. This is the crosspoint modification of mortar methods
   * (Wohlmuth, Discretization methods and iterative solvers based on
   * domain decomposition, 2001, sec. 1.4): the multiplier basis of one
   * interface omits the crosspoint and its neighbour's basis function
   * covers the crosspoint's share, so the joint's weights still sum to
   * its length and its force resultant is unchanged.
   *
   * Which joint keeps the crosspoint: the one listed later (larger
   * ContactNode::joint). The floor scenes list the vertical joints
   * before the bedding, so the bedding keeps the block corners, where it
   * carries the block's weight; the vertical joint's corner pair moves to
   * the node above.
   *
   * @param[in,out] nodes All pairs; the removed ones are erased, the
   *   others keep their order.
   * @param[in] is_exact Per joint index: true for the exact (rigid) law.
   *   Compliant pairs are never removed and make no crosspoint.
   * @return The number of pairs removed.
   */
  template <int dim>
  unsigned int
  remove_crosspoint_pairs(std::vector<ContactNode<dim>> &nodes,
                          const std::vector<bool>       &is_exact);
} // namespace FloorBlock::Contact
