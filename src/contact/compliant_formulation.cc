#include <contact/compliant_formulation.h>
#include <contact/contact_assembly.h>

namespace FloorBlock::Contact
{
  Solver::LinearSolveInfo
  solve_displacement_system(
    Solver::SystemSolver                         &linear_solver,
    const dealii::TrilinosWrappers::SparseMatrix &matrix,
    const dealii::TrilinosWrappers::MPI::Vector  &residual,
    const double                                  forcing,
    dealii::TrilinosWrappers::MPI::Vector        &update)
  {
    dealii::TrilinosWrappers::MPI::Vector right_hand_side(residual);
    right_hand_side *= -1.;
    update = 0.;
    return linear_solver.solve(matrix, right_hand_side, update, forcing);
  }

  template <int dim>
  CompliantFormulation<dim>::CompliantFormulation(
    const ContactSystem<dim>                         &system,
    std::vector<std::unique_ptr<CoulombJoint<dim>>> &&owned_laws,
    const std::vector<const CoulombJoint<dim> *>     &pair_laws)
    : system(system)
    , owned_laws(std::move(owned_laws))
    , pair_laws(pair_laws)
  {}

  template <int dim>
  void
  CompliantFormulation<dim>::reset()
  {}

  template <int dim>
  std::vector<JointResponse<dim>>
  CompliantFormulation<dim>::evaluate(
    const dealii::TrilinosWrappers::MPI::Vector &,
    const dealii::TrilinosWrappers::MPI::Vector &readable_solution,
    const std::vector<JointHistory<dim>>        &histories)
  {
    return evaluate_contact(system.nodes,
                            pair_laws,
                            histories,
                            readable_solution);
  }

  template <int dim>
  const dealii::TrilinosWrappers::SparseMatrix &
  CompliantFormulation<dim>::constant_matrix() const
  {
    return system.bulk.condensed_stiffness();
  }

  template <int dim>
  double
  CompliantFormulation<dim>::add_equations(
    dealii::TrilinosWrappers::SparseMatrix &,
    const dealii::TrilinosWrappers::MPI::Vector &residual)
  {
    return residual.l2_norm();
  }

  template <int dim>
  Solver::LinearSolveInfo
  CompliantFormulation<dim>::solve(
    Solver::SystemSolver                         &linear_solver,
    const dealii::TrilinosWrappers::SparseMatrix &matrix,
    const dealii::TrilinosWrappers::MPI::Vector  &residual,
    const double                                  forcing,
    dealii::TrilinosWrappers::MPI::Vector        &update)
  {
    return solve_displacement_system(
      linear_solver, matrix, residual, forcing, update);
  }

  template <int dim>
  void
  CompliantFormulation<dim>::keep_newton_base()
  {}

  template <int dim>
  void
  CompliantFormulation<dim>::set_step(const double)
  {}

  template <int dim>
  double
  CompliantFormulation<dim>::round_off_floor(
    const dealii::TrilinosWrappers::MPI::Vector &) const
  {
    return 0.;
  }

  template <int dim>
  void
  CompliantFormulation<dim>::converged()
  {}

  template <int dim>
  void
  CompliantFormulation<dim>::commit()
  {}

  template <int dim>
  void
  CompliantFormulation<dim>::discard()
  {}

  template <int dim>
  double
  CompliantFormulation<dim>::complementarity_factor() const
  {
    return 1.;
  }

  template <int dim>
  bool
  CompliantFormulation<dim>::solve_increment(
    const Loading::LoadState           &state,
    const Loading::FailedStartRecorder &record_failed_start,
    const LoadStateStarts<dim>         &starts,
    IncrementResult                    &increment,
    std::string                        &failure_reason)
  {
    return try_plain_starts(
      state, record_failed_start, starts, increment, failure_reason);
  }

  template class CompliantFormulation<2>;
  template class CompliantFormulation<3>;
} // namespace FloorBlock::Contact
