#pragma once

#include <contact/contact_node.h>

#include <deal.II/grid/tria.h>

#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @file
   * @brief The 2D reading of a 3D assembly swept along the face (z,
   * Geometry::extrude_assembly): its joints are 2D joint lines repeated at
   * the slice positions (cross-sections), each standing for a length of
   * face. The solver's pair scales and the joint reports read a 3D joint
   * through these, so that a plane-strain 3D scene gives the 2D answer.
   */

  /**
   * @brief Length of face the mesh stands for (m): 1 in 2D (everything
   * per metre of face), the mesh's extent along z in 3D.
   */
  template <int dim>
  double
  face_length_of(const dealii::Triangulation<dim> &triangulation);

  /**
   * @brief Smallest cell diameter in the x-y plane (m): the smallest cell
   * diameter in 2D; in 3D the smallest diameter of a cell's faces normal
   * to z, i.e. of the 2D cell it was swept from (the slices are usually
   * far thicker than the corner cells, and a joint is resolved across its
   * contact end by the in-plane cells).
   */
  template <int dim>
  double
  smallest_in_plane_cell(const dealii::Triangulation<dim> &triangulation);

  /**
   * @brief The pairs @p members of one 3D joint grouped by cross-section
   * (equal z to 1e-9 of @p face_length), in increasing z.
   */
  std::vector<std::vector<unsigned int>>
  sections_along_face(const std::vector<ContactNode<3>> &nodes,
                      std::vector<unsigned int>          members,
                      const double                       face_length);

  /**
   * @brief Length of face each cross-section of @p sections stands for
   * (m): \f$\ell_k = L\,W_k/W\f$ with \f$W_k\f$ the summed weights of
   * section k, \f$W\f$ the joint's and \f$L\f$ = @p face_length. Exact
   * for the tensor-product shape functions of a swept mesh, where a
   * pair's weight is its 2D weight along the joint line times
   * \f$\ell_k\f$.
   */
  std::vector<double>
  section_lengths(const std::vector<ContactNode<3>>            &nodes,
                  const std::vector<std::vector<unsigned int>> &sections,
                  const double                                  face_length);

  /**
   * @brief Every pair's weight along its joint line (m): its weight in 2D;
   * in 3D its weight over its section's length of face, the weight of the
   * same pair in the 2D scene (zero-weight joints keep 0).
   * @param[in] n_joints Joints the pairs refer to (ContactNode::joint).
   */
  template <int dim>
  std::vector<double>
  weights_along_joint(const std::vector<ContactNode<dim>> &nodes,
                      const unsigned int                   n_joints,
                      const double                         face_length);
} // namespace FloorBlock::Contact
