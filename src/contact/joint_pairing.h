#pragma once

#include <contact/contact_node.h>
#include <fem/fe_space.h>

#include <vector>

namespace FloorBlock::Contact
{
  /** @brief How the nodes of one joint were paired (for tests and reports). */
  struct PairingSummary
  {
    /** Pairs of coincident nodes (initial gap 0). */
    unsigned int n_coincident = 0;
    /** Pairs of mirror-image fillet nodes across the joint (initial gap > 0).
     */
    unsigned int n_mirrored = 0;
    /** Nodes of side A / side B beyond the common part left without a partner
     * (free surface). */
    unsigned int n_free_a = 0;
    unsigned int n_free_b = 0;
  };

  /**
   * @brief Pairs the nodes of boundary @p side_a with those of boundary
   * @p side_b (matching meshes, duplicated vertices), including the corner
   * fillets that face each other across the joint.
   *
   * 1. Coincident nodes (closer than position_tolerance_factor x the
   *    smallest cell diameter) pair with initial gap 0. Weight = integral
   *    of side A's nodal shape function along the joint (degree 1 and 2
   *    alike); normal = weighted mean of side A's outward face normals.
   *    They span the common part of the joint.
   * 2. Nodes beyond either end of the common part (in 3D, a joint swept
   *    along z, cross-section by cross-section): where the two
   *    sides leave the joint line as mirror images -- the top fillets of a
   *    vertical joint on a level floor, meshed with identical node heights
   *    by Geometry::write_gmsh_mesh -- each side-A node pairs with the
   *    side-B node on its normal line, at the same rank counted from the
   *    end of the common part. Normal = the joint normal n (from the chord
   *    of the common part, oriented out of side A), initial gap g0 = (x_B
   *    - x_A).n > 0, weight = integral of N (n_face . n) ds: the length
   *    projected onto the joint line, so that weight x traction is the
   *    force along n. Small sliding: partners are fixed at the start and
   *    the gap is measured along the fixed n, which is valid while the
   *    relative tangential motion and the rotation of the joint stay small
   *    against the fillet size.
   * 3. Other nodes beyond the common part stay unpaired (free surface):
   *    the bottom fillets of a block above a straight base side, or
   *    fillets that are not mirror images (sloped floor at the joint).
   *
   * @param[in] space FE space.
   * @param[in] side_a Boundary id of side A.
   * @param[in] side_b Boundary id of side B.
   * @param[in] joint_index Stored in every pair.
   * @param[out] summary If not null: how many nodes were paired how.
   * @return The pairs; throws InputError if a side is empty, no node has a
   *   coincident partner, or a node on the common part has none
   *   (non-matching mesh).
   */
  template <int dim>
  std::vector<ContactNode<dim>>
  pair_joint_nodes(const Fem::FeSpace<dim>         &space,
                   const dealii::types::boundary_id side_a,
                   const dealii::types::boundary_id side_b,
                   const unsigned int               joint_index,
                   PairingSummary                  *summary = nullptr);

  /**
   * @brief Pairs every node of boundary @p side with a fixed rigid plane,
   * or with a parabolic obstacle touching it at @p plane_point.
   * @param[in] plane_point A point on the plane (m).
   * @param[in] plane_normal Unit normal pointing from the body into the
   *   obstacle; the initial gap is \f$(p_0 - x)\cdot n + \kappa s^2/2\f$,
   *   s the distance of x from p_0 along the plane.
   * @param[in] curvature \f$\kappa\f$ (1/m), >= 0; 0 for the plane.
   */
  template <int dim>
  std::vector<ContactNode<dim>>
  pair_nodes_with_plane(const Fem::FeSpace<dim>         &space,
                        const dealii::types::boundary_id side,
                        const dealii::Point<dim>        &plane_point,
                        const dealii::Tensor<1, dim>    &plane_normal,
                        const double                     curvature,
                        const unsigned int               joint_index);
} // namespace FloorBlock::Contact
