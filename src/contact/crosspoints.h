#pragma once

#include <contact/contact_node.h>

#include <deal.II/base/index_set.h>

#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief Marks the redundant exact-law pairs at crosspoints, where a node
   * lies on two exact joints (a sharp block corner on the bedding).
   *
   * Why: at the corner of two blocks on a base, three coincident nodes
   * form three pairs (the vertical joint and two bedding pairs). Closed and
   * stuck, their six constraints act on two relative displacements and
   * have rank four: the slip of the vertical pair is the difference of the
   * two bedding gaps, and its gap the difference of their slips. Exact
   * multipliers on all three make the Newton matrix singular. In general:
   * with mesh nodes and the rigid obstacle as vertices and exact pairs as
   * edges, every cycle is such a redundancy, and one edge per cycle
   * yields. The yielding pair keeps its place, weight and report but
   * follows the compliant law with springs of the surface stiffness E/h
   * (ContactSolver), which redundancy does not disturb: it may overlap by
   * its traction times h/E, which vanishes under refinement. (Removing the
   * pair instead, the crosspoint modification of mortar methods, let the
   * two corners overlap by the difference of their bedding slips, which
   * does not.)
   *
   * Which pair yields: the edges are taken from the latest joint (largest
   * ContactNode::joint) down, and a pair whose two ends are connected
   * already yields. The floor scenes list the vertical joints before the
   * bedding, so the bedding keeps exact contact at the block corners, where
   * it carries the block's weight, and the vertical joint's corner pair
   * yields.
   *
   * @param[in] nodes All pairs.
   * @param[in] is_exact Per joint index: true for the exact (rigid) law.
   *   Compliant pairs are never marked and close no cycle.
   * @param[in] fixed_dofs Dirichlet DoFs: a node all of whose DoFs are
   *   fixed is the same vertex as the rigid obstacle (the ground), so that
   *   a corner held by a support and standing on a rigid bedding closes a
   *   cycle too.
   * @return Per pair: true if it yields.
   */
  template <int dim>
  std::vector<bool>
  crosspoint_pairs(const std::vector<ContactNode<dim>> &nodes,
                   const std::vector<bool>             &is_exact,
                   const dealii::IndexSet              &fixed_dofs);
} // namespace FloorBlock::Contact
