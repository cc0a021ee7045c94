#include <common/input_error.h>
#include <fem/elastic_assembly.h>
#include <fem/face_values.h>
#include <fem/surface_load.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <string>
#include <vector>

namespace FloorBlock::Fem
{
  namespace
  {
    template <int dim>
    const Material::ElasticLaw<dim> &
    law_of(const ElasticModel<dim> &model, const dealii::types::material_id id)
    {
      const auto found = model.laws.find(id);
      if (found == model.laws.end())
        throw InputError("mesh has material id " + std::to_string(id) +
                         " without an elastic law");
      return found->second;
    }

    template <int dim>
    double
    density_of(const ElasticModel<dim>         &model,
               const dealii::types::material_id id)
    {
      const auto found = model.densities.find(id);
      return found == model.densities.end() ? 0. : found->second;
    }

    /**
     * The cell's body load and, if @p need_matrix, its stiffness matrix
     * (fe_values reinitialised on the cell); adds the body force to
     * @p applied_load_total unless null.
     */
    template <int dim>
    void
    add_cell_integrals(
      const dealii::FEValues<dim>                  &fe_values,
      const dealii::SymmetricTensor<4, dim>        &stiffness,
      const dealii::Tensor<1, dim>                 &body_force,
      const bool                                    need_matrix,
      std::vector<dealii::SymmetricTensor<2, dim>> &strain_basis,
      dealii::FullMatrix<double>                   &cell_matrix,
      dealii::Vector<double>                       &cell_load,
      dealii::Tensor<1, dim> *const                 applied_load_total)
    {
      using namespace dealii;
      const FiniteElement<dim> &fe          = fe_values.get_fe();
      const unsigned int        n_cell_dofs = fe.n_dofs_per_cell();
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const double weight = fe_values.JxW(q);
          for (unsigned int i = 0; i < n_cell_dofs; ++i)
            {
              const unsigned int component =
                fe.system_to_component_index(i).first;
              cell_load(i) +=
                body_force[component] * fe_values.shape_value(i, q) * weight;
              if (need_matrix)
                {
                  Tensor<2, dim> gradient;
                  gradient[component] = fe_values.shape_grad(i, q);
                  strain_basis[i]     = symmetrize(gradient);
                }
            }
          if (need_matrix)
            for (unsigned int i = 0; i < n_cell_dofs; ++i)
              {
                const SymmetricTensor<2, dim> stress_i =
                  stiffness * strain_basis[i];
                for (unsigned int j = 0; j < n_cell_dofs; ++j)
                  cell_matrix(i, j) += stress_i * strain_basis[j] * weight;
              }
          if (applied_load_total != nullptr)
            *applied_load_total += body_force * weight;
        }
    }

    /**
     * The surface loads on the cell's boundary faces added to
     * @p cell_load (and to @p applied_load_total unless null).
     */
    template <int dim, typename CellIterator>
    void
    add_surface_integrals(const ElasticModel<dim>      &model,
                          const CellIterator           &cell,
                          dealii::FEFaceValues<dim>    &face_values,
                          dealii::Vector<double>       &cell_load,
                          dealii::Tensor<1, dim> *const applied_load_total)
    {
      using namespace dealii;
      const FiniteElement<dim> &fe          = face_values.get_fe();
      const unsigned int        n_cell_dofs = fe.n_dofs_per_cell();
      for (const auto &face : cell->face_iterators())
        {
          if (!face->at_boundary())
            continue;
          const auto pressure = model.pressures.find(face->boundary_id());
          if (pressure == model.pressures.end())
            continue;
          face_values.reinit(cell, face);
          for (const unsigned int q : face_values.quadrature_point_indices())
            {
              const Tensor<1, dim> traction =
                surface_traction(model,
                                 face->boundary_id(),
                                 pressure->second,
                                 face_values.normal_vector(q));
              const double weight = face_values.JxW(q);
              for (unsigned int i = 0; i < n_cell_dofs; ++i)
                cell_load(i) +=
                  traction[fe.system_to_component_index(i).first] *
                  face_values.shape_value(i, q) * weight;
              if (applied_load_total != nullptr)
                *applied_load_total += traction * weight;
            }
        }
    }

    /** The cell's matrix and residual into the targets that are set. */
    template <int dim>
    void
    distribute_cell_system(
      const dealii::AffineConstraints<double>            &constraints,
      const dealii::FullMatrix<double>                   &cell_matrix,
      const dealii::Vector<double>                       &cell_residual,
      const std::vector<dealii::types::global_dof_index> &dof_indices,
      const ElasticAssemblyTargets<dim>                  &targets)
    {
      if (targets.matrix != nullptr && targets.residual != nullptr)
        constraints.distribute_local_to_global(cell_matrix,
                                               cell_residual,
                                               dof_indices,
                                               *targets.matrix,
                                               *targets.residual);
      else if (targets.matrix != nullptr)
        constraints.distribute_local_to_global(cell_matrix,
                                               dof_indices,
                                               *targets.matrix);
      else if (targets.residual != nullptr)
        constraints.distribute_local_to_global(cell_residual,
                                               dof_indices,
                                               *targets.residual);
    }
  } // namespace

  template <int dim>
  void
  assemble_elastic_system(const FeSpace<dim>                          &space,
                          const ElasticModel<dim>                     &model,
                          const dealii::TrilinosWrappers::MPI::Vector &solution,
                          const dealii::AffineConstraints<double> &constraints,
                          const ElasticAssemblyTargets<dim>       &targets)
  {
    using namespace dealii;
    const FiniteElement<dim> &fe = space.fe();
    FEValues<dim>             fe_values(space.mapping(),
                            fe,
                            space.cell_quadrature(),
                            update_gradients | update_values |
                              update_JxW_values);
    FEFaceValues<dim>         face_values = boundary_face_values(space);
    const unsigned int        n_cell_dofs = fe.n_dofs_per_cell();
    FullMatrix<double>        cell_matrix(n_cell_dofs, n_cell_dofs);
    Vector<double>            cell_load(n_cell_dofs);
    Vector<double>            cell_displacement(n_cell_dofs);
    Vector<double>            cell_residual(n_cell_dofs);
    std::vector<types::global_dof_index> dof_indices(n_cell_dofs);
    std::vector<SymmetricTensor<2, dim>> strain_basis(n_cell_dofs);

    if (targets.applied_load_total != nullptr)
      *targets.applied_load_total = Tensor<1, dim>();

    CellMatrixCache *const cache = targets.cache;
    const unsigned int     n_cells =
      space.dof_handler().get_triangulation().n_active_cells();
    const bool cache_ready =
      cache != nullptr && cache->matrices.size() == n_cells;
    if (cache != nullptr && !cache_ready)
      cache->matrices.assign(n_cells, FullMatrix<double>());

    for (const auto &cell : space.dof_handler().active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const Material::ElasticLaw<dim> &law =
          law_of(model, cell->material_id());
        const SymmetricTensor<4, dim> &stiffness = law.stiffness_tensor();
        const Tensor<1, dim>           body_force =
          density_of(model, cell->material_id()) * model.gravity;
        const bool need_matrix = !cache_ready;
        fe_values.reinit(cell);
        if (need_matrix)
          cell_matrix = 0.;
        else
          cell_matrix = cache->matrices[cell->active_cell_index()];
        cell_load = 0.;
        add_cell_integrals(fe_values,
                           stiffness,
                           body_force,
                           need_matrix,
                           strain_basis,
                           cell_matrix,
                           cell_load,
                           targets.applied_load_total);
        if (need_matrix && cache != nullptr)
          cache->matrices[cell->active_cell_index()] = cell_matrix;
        add_surface_integrals(
          model, cell, face_values, cell_load, targets.applied_load_total);
        cell->get_dof_indices(dof_indices);
        if (targets.residual != nullptr)
          {
            for (unsigned int i = 0; i < n_cell_dofs; ++i)
              cell_displacement(i) = solution(dof_indices[i]);
            cell_matrix.vmult(cell_residual, cell_displacement);
            cell_residual -= cell_load;
          }
        distribute_cell_system(
          constraints, cell_matrix, cell_residual, dof_indices, targets);
      }
    if (targets.matrix != nullptr)
      targets.matrix->compress(VectorOperation::add);
    if (targets.residual != nullptr)
      targets.residual->compress(VectorOperation::add);
  }

  template void
  assemble_elastic_system(const FeSpace<2> &,
                          const ElasticModel<2> &,
                          const dealii::TrilinosWrappers::MPI::Vector &,
                          const dealii::AffineConstraints<double> &,
                          const ElasticAssemblyTargets<2> &);
  template void
  assemble_elastic_system(const FeSpace<3> &,
                          const ElasticModel<3> &,
                          const dealii::TrilinosWrappers::MPI::Vector &,
                          const dealii::AffineConstraints<double> &,
                          const ElasticAssemblyTargets<3> &);
} // namespace FloorBlock::Fem
