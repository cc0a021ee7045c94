#include <fem/dirichlet_constraints.h>

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/numerics/vector_tools.h>

namespace FloorBlock::Fem
{
  namespace
  {
    /** Adapts a displacement lambda to deal.II's Function interface. */
    template <int dim>
    class DisplacementFunction : public dealii::Function<dim>
    {
    public:
      explicit DisplacementFunction(
        const std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &)>
                  &displacement,
        const bool homogeneous)
        : dealii::Function<dim>(dim)
        , displacement(displacement)
        , homogeneous(homogeneous)
      {}

      double
      value(const dealii::Point<dim> &point,
            const unsigned int        component) const override
      {
        return homogeneous ? 0. : displacement(point)[component];
      }

    private:
      const std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &)>
                &displacement;
      const bool homogeneous;
    };
  } // namespace

  template <int dim>
  dealii::AffineConstraints<double>
  make_constraints(const FeSpace<dim>                         &space,
                   const std::vector<DirichletCondition<dim>> &conditions,
                   const bool                                  homogeneous,
                   dealii::IndexSet                           &dirichlet_dofs,
                   const dealii::IndexSet                     &readable_dofs)
  {
    const dealii::IndexSet &lines =
      readable_dofs.size() > 0 ? readable_dofs : space.locally_relevant_dofs();
    using Merge = dealii::AffineConstraints<double>::MergeConflictBehavior;
    dealii::AffineConstraints<double> constraints;
    constraints.reinit(lines);
    constraints.merge(space.hanging_node_constraints(),
                      Merge::no_conflicts_allowed,
                      true);
    dealii::AffineConstraints<double> dirichlet;
    dirichlet.reinit(lines);
    for (const auto &condition : conditions)
      {
        const DisplacementFunction<dim> function(condition.displacement,
                                                 homogeneous);
        const std::vector<bool> mask(condition.constrained_components.begin(),
                                     condition.constrained_components.end());
        dealii::VectorTools::interpolate_boundary_values(space.mapping(),
                                                         space.dof_handler(),
                                                         condition.boundary_id,
                                                         function,
                                                         dirichlet,
                                                         dealii::ComponentMask(
                                                           mask));
      }
    dirichlet.close();
    dirichlet_dofs = dealii::IndexSet(space.dof_handler().n_dofs());
    for (const auto &line : dirichlet.get_lines())
      dirichlet_dofs.add_index(line.index);
    // Dirichlet values win where a hanging node also sits on a support.
    constraints.merge(dirichlet, Merge::right_object_wins, true);
    const MPI_Comm communicator = space.dof_handler().get_communicator();
    if (dealii::Utilities::MPI::n_mpi_processes(communicator) > 1)
      constraints.make_consistent_in_parallel(space.locally_owned_dofs(),
                                              lines,
                                              communicator);
    constraints.close();
    return constraints;
  }

  template dealii::AffineConstraints<double>
  make_constraints(const FeSpace<2> &,
                   const std::vector<DirichletCondition<2>> &,
                   const bool,
                   dealii::IndexSet &,
                   const dealii::IndexSet &);
  template dealii::AffineConstraints<double>
  make_constraints(const FeSpace<3> &,
                   const std::vector<DirichletCondition<3>> &,
                   const bool,
                   dealii::IndexSet &,
                   const dealii::IndexSet &);
} // namespace FloorBlock::Fem
