#pragma once

#include <contact/contact_node.h>
#include <contact/joint_law.h>
#include <contact/results.h>

#include <string>
#include <vector>

namespace FloorBlock::Postprocess
{
  /**
   * @brief The joint reports of a 3D assembly swept along the face (z,
   * Geometry::extrude_assembly), per metre of face like the 2D ones.
   *
   * Every joint surface of a swept mesh is its 2D joint line times the
   * slice positions, and the lumped weight of a node is the product of its
   * 2D weight along the line and the length of face its slice position
   * stands for (exact for the tensor-product shape functions of a swept
   * hexahedron). So the pairs of one joint at one z form a 2D joint line:
   * each line is reported by make_joint_reports() (closed length with the
   * interpolated contact ends, peaks, profile), with the in-plane parts
   * of positions, normals and tractions and the weights divided by the
   * line's length of face \f$\ell_k = L\,W_k/W\f$ (\f$W_k\f$ the line's
   * summed weights, \f$W\f$ the joint's, \f$L\f$ the face length), and
   * the lines are combined:
   *  - normal and shear force: \f$\sum_k \ell_k N_k / L\f$ (N/m), the
   *    joint's total in-plane force over the face length;
   *  - contact area \f$A = \sum_k \ell_k c_k\f$ (m^2) with \f$c_k\f$ the
   *    line's closed length; JointReport::closed_length = A / L, the
   *    contact length comparable with 2D; the end uncertainty alike;
   *  - pointwise and averaged peak normal stress: the largest over the
   *    lines (the window of the averaged peak runs along the joint line);
   *  - state counts: over every pair; the profile: the line nearest the
   *    middle of the face.
   * The out-of-plane (z) shear of the pairs is not reported: zero under
   * plane strain.
   *
   * @param[in] nodes All contact pairs (3D).
   * @param[in] responses Law evaluations of the converged state.
   * @param[in] names One name per joint; pairs refer to it by index.
   * @param[in] averaging_length Window length of the averaged peak (m).
   * @param[in] face_length Extent of the mesh along z (m), > 0.
   * @return One report per joint, JointReport::face_length = face_length.
   */
  std::vector<Contact::JointReport>
  make_swept_joint_reports(
    const std::vector<Contact::ContactNode<3>>   &nodes,
    const std::vector<Contact::JointResponse<3>> &responses,
    const std::vector<std::string>               &names,
    const double                                  averaging_length,
    const double                                  face_length);
} // namespace FloorBlock::Postprocess
