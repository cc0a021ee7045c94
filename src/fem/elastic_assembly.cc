#include <common/input_error.h>
#include <fem/elastic_assembly.h>
#include <fem/surface_load.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <string>

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
    const FiniteElement<dim>            &fe = space.fe();
    FEValues<dim>                        fe_values(space.mapping(),
                            fe,
                            space.cell_quadrature(),
                            update_gradients | update_values |
                              update_JxW_values);
    FEFaceValues<dim>                    face_values(space.mapping(),
                                  fe,
                                  space.face_quadrature(),
                                  update_values | update_normal_vectors |
                                    update_JxW_values);
    const unsigned int                   n_cell_dofs = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n_cell_dofs, n_cell_dofs);
    Vector<double>                       cell_load(n_cell_dofs);
    Vector<double>                       cell_displacement(n_cell_dofs);
    Vector<double>                       cell_residual(n_cell_dofs);
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
            if (targets.applied_load_total != nullptr)
              *targets.applied_load_total += body_force * weight;
          }
        if (need_matrix && cache != nullptr)
          cache->matrices[cell->active_cell_index()] = cell_matrix;
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
                if (targets.applied_load_total != nullptr)
                  *targets.applied_load_total += traction * weight;
              }
          }
        cell->get_dof_indices(dof_indices);
        if (targets.residual != nullptr)
          {
            for (unsigned int i = 0; i < n_cell_dofs; ++i)
              cell_displacement(i) = solution(dof_indices[i]);
            cell_matrix.vmult(cell_residual, cell_displacement);
            cell_residual -= cell_load;
          }
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
