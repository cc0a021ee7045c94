#include <fem/elastic_assembly.h>
#include <fem/sparsity.h>
#include <fem/stored_elastic_system.h>

#include <Epetra_CrsMatrix.h>

#include <cmath>
#include <stdexcept>

namespace FloorBlock
{
  namespace Fem
  {
    namespace
    {
      using dealii::TrilinosWrappers::MPI::Vector;

      /** Load vector (N) of @p model at u = 0, without constraints. */
      template <int dim>
      void
      assemble_load(const FeSpace<dim>      &space,
                    const ElasticModel<dim> &model,
                    Vector                  &load)
      {
        dealii::AffineConstraints<double> none;
        none.close();
        Vector zero(load);
        zero = 0.;
        load = 0.;
        ElasticAssemblyTargets<dim> targets;
        targets.residual = &load;
        assemble_elastic_system(space, model, zero, none, targets);
        load *= -1.; // the residual at u = 0 is -f
      }
    } // namespace

    template <int dim>
    StoredElasticSystem<dim>::StoredElasticSystem(
      const FeSpace<dim>                              &space,
      const ElasticModel<dim>                         &model,
      const dealii::AffineConstraints<double>         &homogeneous_constraints,
      const dealii::TrilinosWrappers::SparsityPattern &tangent_pattern)
    {
      const dealii::IndexSet &owned = space.locally_owned_dofs();
      for (const auto &line : homogeneous_constraints.get_lines())
        {
          if (line.inhomogeneity != 0.)
            throw std::logic_error("StoredElasticSystem needs homogeneous "
                                   "constraints; DoF " +
                                   std::to_string(line.index) +
                                   " has a prescribed value");
          if (!owned.is_element(line.index))
            continue;
          for (const auto &entry : line.entries)
            if (!owned.is_element(entry.first))
              throw std::logic_error(
                "StoredElasticSystem: master DoF " +
                std::to_string(entry.first) + " of DoF " +
                std::to_string(line.index) + " is not locally owned");
          constrained_dofs.push_back(line.index);
          constraint_entries.emplace_back(line.entries.begin(),
                                          line.entries.end());
        }

      CellMatrixCache cache;
      tangent_stiffness.reinit(tangent_pattern);
      ElasticAssemblyTargets<dim> condensed;
      condensed.matrix = &tangent_stiffness;
      condensed.cache  = &cache;
      const MPI_Comm communicator = space.dof_handler().get_communicator();
      Vector zero(owned, communicator);
      assemble_elastic_system(
        space, model, zero, homogeneous_constraints, condensed);

      dealii::AffineConstraints<double> none;
      none.close();
      make_sparsity(space, none, {}, full_pattern);
      full_stiffness.reinit(full_pattern);
      ElasticAssemblyTargets<dim> full;
      full.matrix = &full_stiffness;
      full.cache  = &cache;
      assemble_elastic_system(space, model, zero, none, full);
      absolute_stiffness.reinit(full_pattern);
      absolute_stiffness.copy_from(full_stiffness);
      Epetra_CrsMatrix &entries =
        const_cast<Epetra_CrsMatrix &>(absolute_stiffness.trilinos_matrix());
      for (int row = 0; row < entries.NumMyRows(); ++row)
        {
          int     n_entries = 0;
          double *values    = nullptr;
          entries.ExtractMyRowView(row, n_entries, values);
          for (int k = 0; k < n_entries; ++k)
            values[k] = std::abs(values[k]);
        }

      ElasticModel<dim> gravity_only = model;
      for (auto &entry : gravity_only.pressures)
        entry.second = 0.;
      ElasticModel<dim> pressure_only = model;
      pressure_only.gravity = dealii::Tensor<1, dim>();
      gravity_load.reinit(owned, communicator);
      pressure_load.reinit(owned, communicator);
      assemble_load(space, gravity_only, gravity_load);
      assemble_load(space, pressure_only, pressure_load);
    }

    template <int dim>
    const dealii::TrilinosWrappers::SparseMatrix &
    StoredElasticSystem<dim>::condensed_stiffness() const
    {
      return tangent_stiffness;
    }

    template <int dim>
    void
    StoredElasticSystem<dim>::residual(const Vector &solution,
                                       const double  gravity_factor,
                                       const double  pressure_factor,
                                       Vector       &residual) const
    {
      full_stiffness.vmult(residual, solution);
      residual.add(-gravity_factor, gravity_load, -pressure_factor, pressure_load);
      for (unsigned int k = 0; k < constrained_dofs.size(); ++k)
        {
          const double constrained_row = residual(constrained_dofs[k]);
          for (const auto &[master, weight] : constraint_entries[k])
            residual(master) += weight * constrained_row;
          residual(constrained_dofs[k]) = 0.;
        }
      residual.compress(dealii::VectorOperation::insert);
    }

    template <int dim>
    double
    StoredElasticSystem<dim>::residual_magnitude(const Vector &solution,
                                                 const double  gravity_factor,
                                                 const double  pressure_factor) const
    {
      Vector magnitude(solution);
      for (auto &value : magnitude)
        value = std::abs(value);
      Vector product(solution);
      absolute_stiffness.vmult(product, magnitude);
      for (const auto dof : product.locally_owned_elements())
        product(dof) += std::abs(gravity_factor * gravity_load(dof)) +
                        std::abs(pressure_factor * pressure_load(dof));
      product.compress(dealii::VectorOperation::insert);
      return product.l2_norm();
    }

    template class StoredElasticSystem<2>;
  } // namespace Fem
} // namespace FloorBlock
