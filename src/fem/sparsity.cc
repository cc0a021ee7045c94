#include <fem/sparsity.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <mpi.h>

namespace FloorBlock::Fem
{
  template <int dim>
  void
  make_sparsity(const FeSpace<dim>                      &space,
                const dealii::AffineConstraints<double> &constraints,
                const std::vector<std::vector<dealii::types::global_dof_index>>
                                                          &coupled_groups,
                dealii::TrilinosWrappers::SparsityPattern &pattern)
  {
    dealii::DynamicSparsityPattern dynamic(space.locally_relevant_dofs());
    dealii::DoFTools::make_sparsity_pattern(space.dof_handler(),
                                            dynamic,
                                            constraints,
                                            false);
    for (const auto &group : coupled_groups)
      constraints.add_entries_local_to_global(group, dynamic, false);
    // A distributed mesh: the rows this process built for DoFs another
    // owns (cells on the partition boundary, joint pairs) go to their
    // owner; on one process nothing moves.
    dealii::SparsityTools::distribute_sparsity_pattern(
      dynamic,
      space.locally_owned_dofs(),
      space.dof_handler().get_communicator(),
      space.locally_relevant_dofs());
    pattern.reinit(space.locally_owned_dofs(),
                   space.locally_owned_dofs(),
                   dynamic,
                   space.dof_handler().get_communicator());
    pattern.compress();
  }

  template void
  make_sparsity(
    const FeSpace<2> &,
    const dealii::AffineConstraints<double> &,
    const std::vector<std::vector<dealii::types::global_dof_index>> &,
    dealii::TrilinosWrappers::SparsityPattern &);
  template void
  make_sparsity(
    const FeSpace<3> &,
    const dealii::AffineConstraints<double> &,
    const std::vector<std::vector<dealii::types::global_dof_index>> &,
    dealii::TrilinosWrappers::SparsityPattern &);
} // namespace FloorBlock::Fem
