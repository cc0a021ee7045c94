#include <fem/fe_space.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>

#include <algorithm>
#include <limits>

namespace FloorBlock::Fem
{
  template <int dim>
  FeSpace<dim>::FeSpace(const dealii::Triangulation<dim> &triangulation,
                        const unsigned int                degree)
    : fe_degree(degree)
    , finite_element(dealii::FE_Q<dim>(degree), dim)
    , mapping_q(degree)
    , cell_gauss(degree + 1)
    , face_gauss(degree + 1)
    , dofs(triangulation)
  {
    dofs.distribute_dofs(finite_element);
    owned    = dofs.locally_owned_dofs();
    relevant = dealii::DoFTools::extract_locally_relevant_dofs(dofs);
    hanging.reinit(relevant);
    dealii::DoFTools::make_hanging_node_constraints(dofs, hanging);
    hanging.close();
    // Over the locally owned cells and then all processes: a distributed
    // mesh's artificial cells are not this process's to measure.
    min_diameter = std::numeric_limits<double>::infinity();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        min_diameter = std::min(min_diameter, cell->diameter());
    min_diameter =
      dealii::Utilities::MPI::min(min_diameter, dofs.get_communicator());
  }

  template <int dim>
  const dealii::DoFHandler<dim> &
  FeSpace<dim>::dof_handler() const
  {
    return dofs;
  }

  template <int dim>
  const dealii::FiniteElement<dim> &
  FeSpace<dim>::fe() const
  {
    return finite_element;
  }

  template <int dim>
  const dealii::Mapping<dim> &
  FeSpace<dim>::mapping() const
  {
    return mapping_q;
  }

  template <int dim>
  const dealii::Quadrature<dim> &
  FeSpace<dim>::cell_quadrature() const
  {
    return cell_gauss;
  }

  template <int dim>
  const dealii::Quadrature<dim - 1> &
  FeSpace<dim>::face_quadrature() const
  {
    return face_gauss;
  }

  template <int dim>
  const dealii::IndexSet &
  FeSpace<dim>::locally_owned_dofs() const
  {
    return owned;
  }

  template <int dim>
  const dealii::IndexSet &
  FeSpace<dim>::locally_relevant_dofs() const
  {
    return relevant;
  }

  template <int dim>
  const dealii::AffineConstraints<double> &
  FeSpace<dim>::hanging_node_constraints() const
  {
    return hanging;
  }

  template <int dim>
  unsigned int
  FeSpace<dim>::degree() const
  {
    return fe_degree;
  }

  template <int dim>
  double
  FeSpace<dim>::minimal_cell_diameter() const
  {
    return min_diameter;
  }

  template class FeSpace<2>;
  template class FeSpace<3>;
} // namespace FloorBlock::Fem
