#include <fem/elastic_assembly.h>
#include <fem/sparsity.h>
#include <fem/stored_elastic_system.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace FloorBlock::Fem
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
      // The cell loop reads u on every DoF of a locally owned cell.
      Vector zero(space.locally_owned_dofs(),
                  space.locally_relevant_dofs(),
                  space.dof_handler().get_communicator());
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
        std::vector<std::pair<std::size_t, double>> masters;
        for (const auto &[master, weight] : line.entries)
          {
            if (!owned.is_element(master))
              throw std::logic_error("StoredElasticSystem: master DoF " +
                                     std::to_string(master) + " of DoF " +
                                     std::to_string(line.index) +
                                     " is not locally owned");
            masters.emplace_back(owned.index_within_set(master), weight);
          }
        constrained_rows.push_back(owned.index_within_set(line.index));
        constraint_entries.push_back(std::move(masters));
      }

    CellMatrixCache cache;
    tangent_stiffness.reinit(tangent_pattern);
    ElasticAssemblyTargets<dim> condensed;
    condensed.matrix            = &tangent_stiffness;
    condensed.cache             = &cache;
    const MPI_Comm communicator = space.dof_handler().get_communicator();
    Vector         zero(owned, space.locally_relevant_dofs(), communicator);
    assemble_elastic_system(
      space, model, zero, homogeneous_constraints, condensed);

    dealii::AffineConstraints<double> none;
    none.close();
    make_sparsity(space, none, {}, full_pattern);
    for (const auto row : owned)
      max_row_length =
        std::max<std::size_t>(max_row_length, full_pattern.row_length(row));
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
    pressure_only.gravity           = dealii::Tensor<1, dim>();
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
    residual.add(-gravity_factor,
                 gravity_load,
                 -pressure_factor,
                 pressure_load);
    // Through the locally owned storage: no compress() (and no
    // collective call) for entries that are all owned here.
    double *const values = residual.begin();
    for (unsigned int k = 0; k < constrained_rows.size(); ++k)
      {
        const double constrained_row = values[constrained_rows[k]];
        for (const auto &[master, weight] : constraint_entries[k])
          values[master] += weight * constrained_row;
        values[constrained_rows[k]] = 0.;
      }
  }

  template <int dim>
  double
  StoredElasticSystem<dim>::residual_magnitude(
    const Vector &solution,
    const double  gravity_factor,
    const double  pressure_factor) const
  {
    Vector magnitude(solution);
    for (auto &value : magnitude)
      value = std::abs(value);
    Vector product(solution);
    absolute_stiffness.vmult(product, magnitude);
    double *const       sum     = product.begin();
    const double *const gravity = gravity_load.begin();
    const double *const load    = pressure_load.begin();
    for (std::size_t i = 0; i < product.locally_owned_size(); ++i)
      sum[i] += std::abs(gravity_factor * gravity[i]) +
                std::abs(pressure_factor * load[i]);
    return product.l2_norm();
  }

  template <int dim>
  double
  StoredElasticSystem<dim>::round_off_floor(const Vector &solution,
                                            const double  gravity_factor,
                                            const double  pressure_factor) const
  {
    // Worst-case error of a sum of m terms: m eps times the sum of their
    // magnitudes; m is the longest stiffness row plus the two loads.
    return (max_row_length + 2) * std::numeric_limits<double>::epsilon() *
           residual_magnitude(solution, gravity_factor, pressure_factor);
  }

  template class StoredElasticSystem<2>;
  template class StoredElasticSystem<3>;
} // namespace FloorBlock::Fem
