#pragma once

#include <contact/contact_problem.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace FloorBlock::Contact
{
  /**
   * @brief Displacement (m) of a moved support point at fraction
   * @p stage_factor (0..1) of the uplift stage.
   *
   * Translations, the parabola and the slope scale linearly with the factor;
   * the tilt is an exact rotation by factor x angle about the pivot, so rigid
   * rotations stay strain-free.
   * @param[in] settings Uplift mode and magnitude.
   * @param[in] stage_factor Fraction of the stage reached (-).
   * @param[in] position Reference position (m).
   *
   * 3D (an assembly swept along z, Geometry::extrude_assembly): the same
   * motion of every cross-section, u_z = 0; x and y as in 2D.
   */
  template <int dim>
  dealii::Tensor<1, dim>
  uplift_displacement(const UpliftSettings     &settings,
                      const double              stage_factor,
                      const dealii::Point<dim> &position);
} // namespace FloorBlock::Contact
