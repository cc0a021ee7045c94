#pragma once

#include <fem/fe_space.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <map>

namespace FloorBlock::Fem
{
  /** @brief Best-fit rigid motion of one body. */
  template <int dim>
  struct RigidMotion
  {
    /** Area-weighted mean displacement of the body (m). */
    dealii::Tensor<1, dim> translation;
    /**
     * Rotation about the body's centroid, counter-clockwise in the x-y
     * plane (rad): 2D, or about the z axis (the face) in 3D.
     */
    double rotation = 0.;
  };

  /**
   * @brief Least-squares rigid motion of each material id, integrated over
   * the body's area (cell quadrature): translation is the mean
   * displacement, rotation \f$\theta = \int r \times u / \int |r|^2\f$
   * with \f$r\f$ the position relative to the centroid (small rotations).
   * Integrals, not sums over vertices: a graded mesh would otherwise
   * weight its finely meshed corners more than the rest of the body.
   * In 3D the rotation is the one about the z axis (the face direction of
   * a swept assembly), fitted from the x-y parts of r and u: the 2D
   * rotation of every cross-section, averaged over the volume.
   * @param[in] space FE space.
   * @param[in] solution Displacement (m).
   * @return One entry per material id present in the mesh.
   */
  template <int dim>
  std::map<dealii::types::material_id, RigidMotion<dim>>
  fit_rigid_motions(const FeSpace<dim>                          &space,
                    const dealii::TrilinosWrappers::MPI::Vector &solution);
} // namespace FloorBlock::Fem
