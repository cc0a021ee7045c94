#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>

namespace FloorBlock::Contact
{
  /**
   * @brief One node pair of a joint (node-to-node on matching meshes), or
   * one node against a rigid plane.
   */
  template <int dim>
  struct ContactNode
  {
    /** Index of the joint in the caller's joint list. */
    unsigned int joint = 0;
    /** Reference position of the side-A node (m). */
    dealii::Point<dim> position;
    /** Lumped interface weight: integral of the node's shape function along the
     * joint (m in 2D). */
    double weight = 0.;
    /** Unit normal from side A to side B (outward normal of side A). */
    dealii::Tensor<1, dim> normal;
    /** Initial gap along the normal (m); zero for matching joints. */
    double initial_gap = 0.;
    /** Displacement DoFs of the side-A node, one per component. */
    std::array<dealii::types::global_dof_index, dim> dofs_a;
    /** Side-B DoFs; all invalid_dof_index when side B is a rigid obstacle. */
    std::array<dealii::types::global_dof_index, dim> dofs_b;
    /**
     * Rigid obstacle only: its prescribed displacement at the load state
     * being solved (m), e.g. a bedding moved parallel to itself; the
     * solver sets it before every evaluation. Zero otherwise.
     */
    dealii::Tensor<1, dim> obstacle_displacement;

    /** @brief True when side B is a fixed rigid obstacle. */
    bool
    against_rigid_obstacle() const
    {
      return dofs_b[0] == dealii::numbers::invalid_dof_index;
    }
  };
} // namespace FloorBlock::Contact
