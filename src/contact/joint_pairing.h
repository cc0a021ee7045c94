#pragma once

#include <contact/contact_node.h>
#include <fem/fe_space.h>

#include <vector>

namespace FloorBlock
{
  namespace Contact
  {
    /**
     * @brief Pairs every node of boundary @p side_a with the coincident node
     * of boundary @p side_b (matching meshes, duplicated vertices).
     *
     * Coincidence tolerance: a fraction position_tolerance_factor of the
     * smallest cell diameter. Weights are the integrals of side A's nodal
     * shape functions along the joint (degree 1 and 2 alike); the normal is
     * the weighted mean of side A's outward face normals.
     *
     * @param[in] space FE space.
     * @param[in] side_a Boundary id of side A.
     * @param[in] side_b Boundary id of side B.
     * @param[in] joint_index Stored in every pair.
     * @return The pairs; throws InputError if a side is empty or a node has
     *   no partner (non-matching mesh).
     */
    template <int dim>
    std::vector<ContactNode<dim>>
    pair_joint_nodes(const Fem::FeSpace<dim>         &space,
                     const dealii::types::boundary_id side_a,
                     const dealii::types::boundary_id side_b,
                     const unsigned int               joint_index);

    /**
     * @brief Pairs every node of boundary @p side with a fixed rigid plane.
     * @param[in] plane_point A point on the plane (m).
     * @param[in] plane_normal Unit normal pointing from the body into the
     *   obstacle; the initial gap is \f$(p_0 - x)\cdot n\f$.
     */
    template <int dim>
    std::vector<ContactNode<dim>>
    pair_nodes_with_plane(const Fem::FeSpace<dim>         &space,
                          const dealii::types::boundary_id side,
                          const dealii::Point<dim>        &plane_point,
                          const dealii::Tensor<1, dim>    &plane_normal,
                          const unsigned int               joint_index);
  } // namespace Contact
} // namespace FloorBlock
