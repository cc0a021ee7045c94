#pragma once

#include <fem/fe_space.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <functional>
#include <vector>

namespace FloorBlock::Fem
{
  /**
   * @brief A prescribed displacement on one boundary id.
   *
   * Only the components flagged in @p constrained_components are fixed;
   * @p displacement gives their values (m) as a function of the reference
   * position (m).
   */
  template <int dim>
  struct DirichletCondition
  {
    dealii::types::boundary_id boundary_id;
    std::array<bool, dim>      constrained_components;
    std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &)>
      displacement;
  };

  /**
   * @brief Hanging-node constraints merged with the Dirichlet conditions.
   * @param[in] space The FE space.
   * @param[in] conditions Prescribed displacements.
   * @param[in] homogeneous If true, all prescribed values are zero (the
   *   constraints of a Newton update).
   * @param[out] dirichlet_dofs The DoFs fixed by @p conditions (not the
   *   hanging ones) among the locally relevant ones: the supports whose
   *   reactions are reported.
   * @param[in] readable_dofs The DoFs whose constraints this process must
   *   know: empty for the locally relevant ones; on a distributed mesh
   *   also the joint pairs' DoFs, which another process may own and
   *   constrain (the constraints are then made consistent over the
   *   processes).
   * @return Closed constraints.
   */
  template <int dim>
  dealii::AffineConstraints<double>
  make_constraints(const FeSpace<dim>                         &space,
                   const std::vector<DirichletCondition<dim>> &conditions,
                   const bool                                  homogeneous,
                   dealii::IndexSet                           &dirichlet_dofs,
                   const dealii::IndexSet &readable_dofs = dealii::IndexSet());
} // namespace FloorBlock::Fem
