#include <fem/rigid_body_modes.h>

#include <deal.II/dofs/dof_tools.h>

#include <map>

namespace FloorBlock::Fem
{
  template <int dim>
  Solver::NearNullSpace
  rigid_body_modes(const FeSpace<dim> &space)
  {
    const dealii::DoFHandler<dim> &dofs  = space.dof_handler();
    const dealii::IndexSet        &owned = space.locally_owned_dofs();
    std::map<dealii::types::global_dof_index, dealii::Point<dim>> points;
    dealii::DoFTools::map_dofs_to_support_points(space.mapping(), dofs, points);
    std::vector<unsigned int> component(owned.n_elements(), 0);
    std::vector<dealii::types::global_dof_index> cell_dofs(
      space.fe().n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            if (owned.is_element(cell_dofs[i]))
              component[owned.index_within_set(cell_dofs[i])] =
                space.fe().system_to_component_index(i).first;
        }

    constexpr unsigned int n_rotations = dim == 2 ? 1 : 3;
    Solver::NearNullSpace  null_space;
    null_space.n_components = dim;
    null_space.modes.assign(dim + n_rotations,
                            std::vector<double>(owned.n_elements(), 0.));
    for (const auto &[index, point] : points)
      {
        if (!owned.is_element(index))
          continue;
        const std::size_t  row   = owned.index_within_set(index);
        const unsigned int c     = component[row];
        null_space.modes[c][row] = 1.;
        // Rotation about axis a moves x by e_a x x: about z (-y, x, 0),
        // about x (0, -z, y), about y (z, 0, -x).
        const double x             = point[0];
        const double y             = point[1];
        null_space.modes[dim][row] = c == 0 ? -y : c == 1 ? x : 0.;
        if constexpr (dim == 3)
          {
            const double z                 = point[2];
            null_space.modes[dim + 1][row] = c == 0 ? 0. : c == 1 ? -z : y;
            null_space.modes[dim + 2][row] = c == 0 ? z : c == 1 ? 0. : -x;
          }
      }
    return null_space;
  }

  template Solver::NearNullSpace
  rigid_body_modes(const FeSpace<2> &);
  template Solver::NearNullSpace
  rigid_body_modes(const FeSpace<3> &);
} // namespace FloorBlock::Fem
