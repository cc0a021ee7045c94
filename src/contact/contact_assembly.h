#pragma once

#include <contact/contact_node.h>
#include <contact/joint_law.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief Evaluates the joint law of every pair at the displacement
   * @p solution.
   * @param[in] nodes Contact pairs.
   * @param[in] laws One law per pair (the law of the pair's joint); a
   *   null law (an exact-law pair, see ExactContact) leaves the pair's
   *   response at its default.
   * @param[in] histories One history per pair.
   * @param[in] solution Displacement (m); on a distributed mesh a
   *   ghosted vector that reads every pair's DoFs (pair_dofs()).
   */
  template <int dim>
  std::vector<JointResponse<dim>>
  evaluate_contact(const std::vector<ContactNode<dim>>          &nodes,
                   const std::vector<const CoulombJoint<dim> *> &laws,
                   const std::vector<JointHistory<dim>>         &histories,
                   const dealii::TrilinosWrappers::MPI::Vector  &solution);

  /**
   * @brief Adds the pairs' internal forces \f$\pm w\,(−t_n n + t_t)\f$ to
   * @p residual and their tangents to @p matrix (either may be null),
   * distributed with @p constraints. The matrix may be larger than the
   * residual (the exact law's system, displacements and multipliers).
   * A pair is added by the process that owns its side-A x DoF only (on a
   * distributed mesh every process holds every pair).
   */
  template <int dim>
  void
  assemble_contact(const std::vector<ContactNode<dim>>     &nodes,
                   const std::vector<JointResponse<dim>>   &responses,
                   const dealii::AffineConstraints<double> &constraints,
                   dealii::TrilinosWrappers::SparseMatrix  *matrix,
                   dealii::TrilinosWrappers::MPI::Vector   *residual);

  /**
   * @brief Every DoF of every pair: what a process must read to evaluate
   * all pairs (the ghosts of a distributed solution).
   */
  template <int dim>
  dealii::IndexSet
  pair_dofs(const std::vector<ContactNode<dim>>  &nodes,
            const dealii::types::global_dof_index n_dofs);

  /** @brief The DoFs of each pair, for the sparsity pattern. */
  template <int dim>
  std::vector<std::vector<dealii::types::global_dof_index>>
  pair_dof_groups(const std::vector<ContactNode<dim>> &nodes);
} // namespace FloorBlock::Contact
