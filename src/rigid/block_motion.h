#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>

namespace FloorBlock::RigidBlocks
{
  /**
   * @brief Rigid motion of one block: translation of its centroid and a
   * rotation about it.
   *
   * Small rotations: a point p moves by
   * \f$ u(p) = u_c + \theta\, e_z \times (p - c) =
   * (u_{c,x} - \theta (p_y - c_y),\; u_{c,y} + \theta (p_x - c_x)) \f$.
   * This is the linearised rotation; the exact one differs by
   * \f$O(\theta^2 |p - c|)\f$, i.e. a relative error of \f$\theta/2\f$ in
   * the displacement of a corner (5e-4 at the 1e-3 rad the chapter's
   * floors produce). It keeps every joint law piecewise linear in the
   * motion, and makes the Winkler overlap of Eq. 6.51 exactly linear.
   */
  struct BlockMotion
  {
    /** Displacement of the centroid (m). */
    dealii::Tensor<1, 2> translation;
    /** Counter-clockwise rotation about the centroid (rad). */
    double rotation = 0.;
  };

  /**
   * @brief Displacement of @p point of a block with centroid @p centroid
   * under @p motion (m), small-rotation kinematics.
   */
  dealii::Tensor<1, 2>
  point_displacement(const BlockMotion      &motion,
                     const dealii::Point<2> &centroid,
                     const dealii::Point<2> &point);

  /**
   * @brief Derivatives of point_displacement() with respect to
   * (u_x, u_y, theta): column k is \f$\partial u(p)/\partial q_k\f$
   * (m/m, m/m, m/rad).
   */
  std::array<dealii::Tensor<1, 2>, 3>
  displacement_derivatives(const dealii::Point<2> &centroid,
                           const dealii::Point<2> &point);
} // namespace FloorBlock::RigidBlocks
