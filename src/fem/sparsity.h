#pragma once

#include <fem/fe_space.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <vector>

namespace FloorBlock::Fem
{
  /**
   * @brief Sparsity of the bulk stiffness plus extra couplings.
   *
   * @param[in] space FE space.
   * @param[in] constraints Constraints the matrix is assembled with.
   * @param[in] coupled_groups Each group is a set of DoFs that couple all
   *   to all, e.g. the two sides of one joint node pair.
   * @param[out] pattern The compressed pattern.
   */
  template <int dim>
  void
  make_sparsity(const FeSpace<dim>                      &space,
                const dealii::AffineConstraints<double> &constraints,
                const std::vector<std::vector<dealii::types::global_dof_index>>
                                                          &coupled_groups,
                dealii::TrilinosWrappers::SparsityPattern &pattern);
} // namespace FloorBlock::Fem
