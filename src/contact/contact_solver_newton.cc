#include <contact/contact_assembly.h>
#include <contact/contact_setup.h>
#include <contact/contact_solver.h>
#include <contact/uplift.h>
#include <fem/dirichlet_constraints.h>

#include <algorithm>
#include <cmath>

// The Newton iteration of one load state: ContactSolver's members that
// build and solve its systems, with the formulation's part added.
namespace FloorBlock::Contact
{
  template <int dim>
  void
  ContactSolver<dim>::move_obstacles(const double uplift_factor)
  {
    for (auto &node : nodes)
      if (problem.joints[node.joint].plane_moves_with_uplift)
        node.obstacle_displacement =
          uplift_displacement(problem.uplift, uplift_factor, node.position);
  }

  template <int dim>
  double
  ContactSolver<dim>::load_norm(const Loading::LoadFactors &factors)
  {
    dealii::TrilinosWrappers::MPI::Vector zero(current_solution);
    zero = 0.;
    bulk->residual(zero, factors.gravity, factors.support, residual);
    return residual.l2_norm();
  }

  template <int dim>
  NewtonIterate
  ContactSolver<dim>::assemble_iterate(const Loading::LoadFactors &factors)
  {
    dealii::TimerOutput::Scope            scope(timer, "Contact: assemble");
    const std::vector<JointResponse<dim>> responses = responses_at_iterate();
    matrix.copy_from(formulation->constant_matrix());
    bulk->residual(current_solution,
                   factors.gravity,
                   factors.support,
                   residual);
    assemble_contact(
      nodes, responses, homogeneous_constraints, &matrix, &residual);
    NewtonIterate iterate;
    iterate.residual_norm = formulation->add_equations(matrix, residual);
    active_set.update(states_of(responses));
    iterate.set_signature = active_set.signature();
    iterate.counts        = active_set.counts();
    last_iterate_counts   = iterate.counts;
    console << "    residual " << iterate.residual_norm
            << " N, stick/slip/open " << iterate.counts.n_stick << "/"
            << iterate.counts.n_slip << "/" << iterate.counts.n_open
            << std::endl;
    return iterate;
  }

  template <int dim>
  bool
  ContactSolver<dim>::solve_update(const double forcing, std::string &message)
  {
    dealii::TimerOutput::Scope scope(timer, "Contact: linear solve");
    ++n_linear_solves;
    const Solver::LinearSolveInfo info =
      formulation->solve(*linear_solver, matrix, residual, forcing, update);
    message = info.message;
    if (!info.success)
      return false;
    homogeneous_constraints.distribute(update);
    newton_base = current_solution;
    formulation->keep_newton_base();
    return true;
  }

  template <int dim>
  bool
  ContactSolver<dim>::solve_load_state(const Loading::LoadFactors &factors,
                                       const double                prediction,
                                       IncrementResult            &increment,
                                       std::string &failure_reason)
  {
    const dealii::AffineConstraints<double> constraints = [&]() {
      dealii::TimerOutput::Scope scope(timer, "Contact: constraints");
      return Fem::make_constraints(fe_space,
                                   support_conditions(problem, factors.uplift),
                                   false,
                                   dirichlet_dofs);
    }();
    constraints.distribute(current_solution);
    move_obstacles(factors.uplift);
    double reference_load = load_norm(factors);

    NewtonCallbacks callbacks;
    callbacks.assemble     = [&]() { return assemble_iterate(factors); };
    callbacks.solve_update = [&](const double forcing, std::string &message) {
      return solve_update(forcing, message);
    };
    callbacks.set_step = [&](const double step) {
      current_solution = newton_base;
      current_solution.add(step, update);
      formulation->set_step(step);
    };
    callbacks.round_off_floor = [&]() {
      return std::hypot(bulk->round_off_floor(current_solution,
                                              factors.gravity,
                                              factors.support),
                        formulation->round_off_floor(current_solution));
    };
    if (prediction > 0.)
      {
        // The stop test stays relative to the larger of the load and the
        // residual at the last converged state, as without the predictor:
        // the predictor changes where Newton starts, not when it stops.
        // (Relative to the load alone, a 1e-12 tolerance fell below the
        // round-off of K u under a large uplift.)
        reference_load =
          std::max(reference_load, callbacks.assemble().residual_norm);
        current_solution.add(prediction, last_change);
        constraints.distribute(current_solution);
        // The multipliers start from the last converged state: their
        // extrapolation too made the predictor useless on the lifted
        // floor (58 Newton iterations plain, 59 with both extrapolated,
        // 32 with the displacements alone).
      }
    const NewtonReport report =
      solve_newton(settings.newton,
                   reference_load,
                   callbacks,
                   prediction > 0. ? ReferenceForce::given :
                                     ReferenceForce::given_or_first_residual);
    increment.n_newton_iterations = report.n_iterations;
    increment.round_off_limited   = report.stopped_at_round_off_floor;
    increment.relative_residual   = report.relative_residual;
    if (!report.converged)
      failure_reason = report.failure_reason;
    else
      formulation->converged();
    return report.converged;
  }

  template <int dim>
  std::vector<JointResponse<dim>>
  ContactSolver<dim>::responses_at_iterate()
  {
    readable_solution = current_solution;
    return formulation->evaluate(current_solution,
                                 readable_solution,
                                 working_history);
  }

  // Only the members of this file: contact_solver.cc instantiates the
  // class.
#define FLOORBLOCK_INSTANTIATE(dim)                                            \
  template void   ContactSolver<dim>::move_obstacles(const double);            \
  template double ContactSolver<dim>::load_norm(const Loading::LoadFactors &); \
  template NewtonIterate ContactSolver<dim>::assemble_iterate(                 \
    const Loading::LoadFactors &);                                             \
  template bool ContactSolver<dim>::solve_update(const double, std::string &); \
  template bool ContactSolver<dim>::solve_load_state(                          \
    const Loading::LoadFactors &,                                              \
    const double,                                                              \
    IncrementResult &,                                                         \
    std::string &);                                                            \
  template std::vector<JointResponse<dim>>                                     \
  ContactSolver<dim>::responses_at_iterate();
  FLOORBLOCK_INSTANTIATE(2)
  FLOORBLOCK_INSTANTIATE(3)
#undef FLOORBLOCK_INSTANTIATE
} // namespace FloorBlock::Contact
