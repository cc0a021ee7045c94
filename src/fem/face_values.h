#pragma once

#include <fem/fe_space.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

namespace FloorBlock::Fem
{
  /**
   * @brief Face values for integrals over boundary faces: shape values,
   * outward normals and JxW at the quadrature points.
   * @param[in] mapping, fe, quadrature Must outlive the result.
   * Returned as a prvalue (FEFaceValues can be neither copied nor moved).
   */
  template <int dim>
  dealii::FEFaceValues<dim>
  boundary_face_values(const dealii::Mapping<dim>        &mapping,
                       const dealii::FiniteElement<dim>  &fe,
                       const dealii::Quadrature<dim - 1> &quadrature);

  /**
   * @brief boundary_face_values() with the mapping, element and face
   * quadrature of @p space.
   */
  template <int dim>
  dealii::FEFaceValues<dim>
  boundary_face_values(const FeSpace<dim> &space);
} // namespace FloorBlock::Fem
