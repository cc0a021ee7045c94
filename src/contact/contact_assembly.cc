#include <contact/contact_assembly.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>

namespace FloorBlock::Contact
{
  template <int dim>
  std::vector<JointResponse<dim>>
  evaluate_contact(const std::vector<ContactNode<dim>>          &nodes,
                   const std::vector<const CoulombJoint<dim> *> &laws,
                   const std::vector<JointHistory<dim>>         &histories,
                   const dealii::TrilinosWrappers::MPI::Vector  &solution)
  {
    std::vector<JointResponse<dim>> responses(nodes.size());
    for (unsigned int p = 0; p < nodes.size(); ++p)
      {
        if (laws[p] == nullptr)
          continue;
        const ContactNode<dim> &node = nodes[p];
        dealii::Tensor<1, dim>  jump = node.initial_gap * node.normal;
        for (unsigned int c = 0; c < dim; ++c)
          {
            jump[c] -= solution(node.dofs_a[c]);
            jump[c] += node.against_rigid_obstacle() ?
                         node.obstacle_displacement[c] :
                         solution(node.dofs_b[c]);
          }
        responses[p] = laws[p]->evaluate(jump, node.normal, histories[p]);
      }
    return responses;
  }

  template <int dim>
  std::vector<std::vector<dealii::types::global_dof_index>>
  pair_dof_groups(const std::vector<ContactNode<dim>> &nodes)
  {
    std::vector<std::vector<dealii::types::global_dof_index>> groups;
    for (const auto &node : nodes)
      {
        std::vector<dealii::types::global_dof_index> group(node.dofs_b.begin(),
                                                           node.dofs_b.end());
        if (node.against_rigid_obstacle())
          group.clear();
        group.insert(group.end(), node.dofs_a.begin(), node.dofs_a.end());
        groups.push_back(group);
      }
    return groups;
  }

  template <int dim>
  dealii::IndexSet
  pair_dofs(const std::vector<ContactNode<dim>>  &nodes,
            const dealii::types::global_dof_index n_dofs)
  {
    dealii::IndexSet dofs(n_dofs);
    for (const auto &group : pair_dof_groups(nodes))
      {
        std::vector<dealii::types::global_dof_index> sorted = group;
        std::sort(sorted.begin(), sorted.end());
        dofs.add_indices(sorted.begin(), sorted.end());
      }
    dofs.compress();
    return dofs;
  }

  template <int dim>
  void
  assemble_contact(const std::vector<ContactNode<dim>>     &nodes,
                   const std::vector<JointResponse<dim>>   &responses,
                   const dealii::AffineConstraints<double> &constraints,
                   dealii::TrilinosWrappers::SparseMatrix  *matrix,
                   dealii::TrilinosWrappers::MPI::Vector   *residual)
  {
    const std::vector<std::vector<dealii::types::global_dof_index>> groups =
      pair_dof_groups(nodes);
    // Every process holds every pair; the one owning side A's first DoF
    // adds it (off-process rows reach their owner in compress()), so that
    // a distributed system counts each pair once.
    const dealii::IndexSet owned =
      residual != nullptr ? residual->locally_owned_elements() :
      matrix != nullptr   ? matrix->locally_owned_range_indices() :
                            dealii::IndexSet();
    for (unsigned int p = 0; p < nodes.size(); ++p)
      {
        if (!owned.is_element(nodes[p].dofs_a[0]))
          continue;
        const JointResponse<dim> &response = responses[p];
        const double              weight   = nodes[p].weight;
        // Local order: side B components first (if deformable), then A;
        // B gets +w f and +w D, A gets the opposite, cross terms -w D.
        const bool         two_sided = !nodes[p].against_rigid_obstacle();
        const unsigned int n_sides   = two_sided ? 2 : 1;
        const unsigned int n_local   = n_sides * dim;
        dealii::FullMatrix<double> local_matrix(n_local, n_local);
        dealii::Vector<double>     local_residual(n_local);
        for (unsigned int side_i = 0; side_i < n_sides; ++side_i)
          {
            // Sign of side i: +1 for B, -1 for A.
            const double sign_i = (two_sided && side_i == 0) ? 1. : -1.;
            for (unsigned int i = 0; i < dim; ++i)
              {
                local_residual(side_i * dim + i) =
                  sign_i * weight * response.force_density[i];
                for (unsigned int side_j = 0; side_j < n_sides; ++side_j)
                  {
                    const double sign_j = (two_sided && side_j == 0) ? 1. : -1.;
                    for (unsigned int j = 0; j < dim; ++j)
                      local_matrix(side_i * dim + i, side_j * dim + j) =
                        sign_i * sign_j * weight * response.tangent[i][j];
                  }
              }
          }
        // The exact law's matrix also holds the multipliers' rows, so it
        // is larger than the displacement residual; deal.II distributes a
        // matrix and a vector together only if their sizes agree.
        if (matrix != nullptr && residual != nullptr &&
            matrix->m() == residual->size())
          constraints.distribute_local_to_global(
            local_matrix, local_residual, groups[p], *matrix, *residual);
        else if (matrix != nullptr && residual != nullptr)
          {
            constraints.distribute_local_to_global(local_matrix,
                                                   groups[p],
                                                   *matrix);
            constraints.distribute_local_to_global(local_residual,
                                                   groups[p],
                                                   *residual);
          }
        else if (matrix != nullptr)
          constraints.distribute_local_to_global(local_matrix,
                                                 groups[p],
                                                 *matrix);
        else if (residual != nullptr)
          constraints.distribute_local_to_global(local_residual,
                                                 groups[p],
                                                 *residual);
      }
    if (matrix != nullptr)
      matrix->compress(dealii::VectorOperation::add);
    if (residual != nullptr)
      residual->compress(dealii::VectorOperation::add);
  }

  template std::vector<JointResponse<2>>
  evaluate_contact(const std::vector<ContactNode<2>> &,
                   const std::vector<const CoulombJoint<2> *> &,
                   const std::vector<JointHistory<2>> &,
                   const dealii::TrilinosWrappers::MPI::Vector &);
  template void
  assemble_contact(const std::vector<ContactNode<2>> &,
                   const std::vector<JointResponse<2>> &,
                   const dealii::AffineConstraints<double> &,
                   dealii::TrilinosWrappers::SparseMatrix *,
                   dealii::TrilinosWrappers::MPI::Vector *);
  template std::vector<std::vector<dealii::types::global_dof_index>>
  pair_dof_groups(const std::vector<ContactNode<2>> &);
  template dealii::IndexSet
  pair_dofs(const std::vector<ContactNode<2>> &,
            const dealii::types::global_dof_index);
  template dealii::IndexSet
  pair_dofs(const std::vector<ContactNode<3>> &,
            const dealii::types::global_dof_index);
  template std::vector<JointResponse<3>>
  evaluate_contact(const std::vector<ContactNode<3>> &,
                   const std::vector<const CoulombJoint<3> *> &,
                   const std::vector<JointHistory<3>> &,
                   const dealii::TrilinosWrappers::MPI::Vector &);
  template void
  assemble_contact(const std::vector<ContactNode<3>> &,
                   const std::vector<JointResponse<3>> &,
                   const dealii::AffineConstraints<double> &,
                   dealii::TrilinosWrappers::SparseMatrix *,
                   dealii::TrilinosWrappers::MPI::Vector *);
  template std::vector<std::vector<dealii::types::global_dof_index>>
  pair_dof_groups(const std::vector<ContactNode<3>> &);
} // namespace FloorBlock::Contact
