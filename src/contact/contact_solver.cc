#include <common/interrupt.h>
#include <contact/contact_assembly.h>
#include <contact/contact_setup.h>
#include <contact/contact_solver.h>
#include <contact/joint_pairing.h>
#include <fem/dirichlet_constraints.h>
#include <fem/rigid_body_modes.h>
#include <fem/sparsity.h>

#include <deal.II/base/mpi.h>

#include <iostream>
#include <stdexcept>

namespace FloorBlock::Contact
{
  template <int dim>
  ContactSolver<dim>::ContactSolver(
    const dealii::Triangulation<dim> &triangulation,
    const ContactProblem<dim>        &problem,
    const ContactSolverSettings      &settings)
    : problem(problem)
    , settings(settings)
    , fe_space(triangulation, settings.fe_degree)
    , console(std::cout,
              settings.verbose && dealii::Utilities::MPI::this_mpi_process(
                                    triangulation.get_communicator()) == 0)
    , timer(console,
            dealii::TimerOutput::never,
            dealii::TimerOutput::wall_times)
  {
    // A distributed mesh (several processes): every process pairs and
    // evaluates every joint node (joint_pairing.h, contact_assembly.h),
    // the bulk and the linear algebra are distributed. The exact law's
    // multipliers and the kept LU factors are not (yet): refused.
    const MPI_Comm communicator = fe_space.dof_handler().get_communicator();
    const bool     distributed =
      dealii::Utilities::MPI::n_mpi_processes(communicator) > 1;
    dealii::TimerOutput::Scope scope(timer, "Contact: setup");
    const auto zero_conditions = support_conditions(problem, std::nullopt);
    homogeneous_constraints =
      Fem::make_constraints(fe_space, zero_conditions, true, dirichlet_dofs);
    nodes = pair_all_joints(fe_space, problem);
    // After the supports: a node they hold is ground for the crosspoints.
    PairLaws<dim> laws = make_pair_laws(fe_space,
                                        problem,
                                        nodes,
                                        dirichlet_dofs,
                                        settings.complementarity_factor);
    if (laws.n_crosspoint_pairs > 0)
      console << "  " << laws.n_crosspoint_pairs
              << " rigid-law pairs at crosspoints follow springs of the "
                 "surface stiffness"
              << std::endl;
    committed_history.assign(nodes.size(), JointHistory<dim>());
    working_history = committed_history;
    stiffness_hint  = Contact::stiffness_hint(fe_space, problem, nodes);
    readable_dofs   = fe_space.locally_relevant_dofs();
    readable_dofs.add_indices(
      pair_dofs(nodes, fe_space.dof_handler().n_dofs()));
    // A process adds the pairs whose side A it owns: it must know whether
    // the partner's DoFs, which another process may own, are held.
    if (distributed)
      homogeneous_constraints = Fem::make_constraints(
        fe_space, zero_conditions, true, dirichlet_dofs, readable_dofs);
    Fem::make_sparsity(fe_space,
                       homogeneous_constraints,
                       pair_dof_groups(nodes),
                       pattern);
    matrix.reinit(pattern);
    bulk = std::make_unique<Fem::StoredElasticSystem<dim>>(
      fe_space, problem.model, homogeneous_constraints, pattern);
    const bool exact = laws.any_exact();
    if (exact && distributed)
      throw std::logic_error(
        "the exact (rigid) joint law runs on one process only");
    formulation = make_contact_formulation(
      {nodes, homogeneous_constraints, *bulk}, laws, pattern, matrix, console);
    linear_solver = std::make_unique<Solver::SystemSolver>(
      settings.linear,
      Solver::SystemDescription{fe_space.dof_handler().n_dofs(), exact},
      communicator,
      [this]() { return Fem::rigid_body_modes(fe_space); });
    // The triangulation's communicator: MPI_COMM_SELF for a serial mesh,
    // so that every rank of a sweep solves its own case independently.
    const dealii::IndexSet &owned = fe_space.locally_owned_dofs();
    for (auto *vector : {&current_solution,
                         &committed_solution,
                         &newton_base,
                         &update,
                         &residual,
                         &last_change})
      vector->reinit(owned, communicator);
    readable_solution.reinit(owned, readable_dofs, communicator);
  }

  template <int dim>
  SolveResult
  ContactSolver<dim>::run(IncrementObserver<dim> &observer)
  {
    SolveResult result;
    result.n_dofs          = fe_space.dof_handler().n_dofs();
    result.n_contact_pairs = nodes.size();
    current_solution       = 0.;
    committed_solution     = 0.;
    formulation->reset();

    IncrementResult            increment;
    dealii::Timer              clock;
    Loading::LoadPathCallbacks callbacks;
    callbacks.solve = [&](const Loading::LoadState           &state,
                          const Loading::FailedStartRecorder &record_failure,
                          std::string                        &reason) {
      clock.restart();
      return solve_increment(state, record_failure, increment, reason);
    };
    callbacks.commit = [&](const Loading::LoadState &state) {
      commit_increment(state, clock, observer, increment, result);
    };
    callbacks.discard = [&](const std::string &attempt) {
      discard_attempt(attempt, increment);
    };
    // A safe point for Ctrl-C / SIGTERM: the caller discards the whole
    // solve, so nothing half-computed reaches a result file.
    callbacks.at_safe_point = stop_if_interrupted;

    const Loading::LoadPathOutcome outcome =
      Loading::follow_load_path(problem.steps,
                                settings.max_cutbacks,
                                callbacks);
    add_statistics(result);
    if (!outcome.completed)
      {
        ContactSolveFailure failure(
          std::string("contact solve failed in stage '") +
            Loading::stage_name(outcome.failed_stage) + "' after " +
            std::to_string(settings.max_cutbacks) +
            " cutbacks: " + outcome.failure_reason + stiffness_hint,
          outcome.failed_attempts,
          result.increments.empty() ?
            std::nullopt :
            std::optional<IncrementResult>(result.increments.back()),
          last_iterate_counts);
        failure.partial_result = result;
        throw failure;
      }
    return result;
  }

  template <int dim>
  bool
  ContactSolver<dim>::solve_increment(
    const Loading::LoadState           &state,
    const Loading::FailedStartRecorder &record_failed_start,
    IncrementResult                    &increment,
    std::string                        &failure_reason)
  {
    LoadStateStarts<dim> starts;
    starts.solve = [this](const Loading::LoadFactors &factors,
                          const double                prediction,
                          IncrementResult            &result,
                          std::string                &reason) {
      return solve_load_state(factors, prediction, result, reason);
    };
    starts.responses_at_iterate = [this]() { return responses_at_iterate(); };
    starts.prediction =
      settings.extrapolate_increments ? state.prediction_ratio : 0.;
    return formulation->solve_increment(
      state, record_failed_start, starts, increment, failure_reason);
  }

  template <int dim>
  void
  ContactSolver<dim>::commit_increment(const Loading::LoadState &state,
                                       const dealii::Timer      &clock,
                                       IncrementObserver<dim>   &observer,
                                       IncrementResult          &increment,
                                       SolveResult              &result)
  {
    dealii::TimerOutput::Scope            scope(timer, "Contact: post-process");
    const std::vector<JointResponse<dim>> responses = responses_at_iterate();
    increment.stage                                 = state.stage;
    increment.stage_factor                          = state.stage_factor;
    increment.n_cutbacks                            = state.n_cutbacks;
    increment.complementarity_factor = formulation->complementarity_factor();
    increment.counts                 = count_states(states_of(responses));
    // readable_solution holds current_solution: responses_at_iterate().
    observer.describe(state.factors, responses, readable_solution, increment);
    last_change = current_solution;
    last_change -= committed_solution;
    committed_solution  = current_solution;
    committed_responses = responses;
    formulation->commit();
    commit_histories(responses, committed_history);
    working_history     = committed_history;
    increment.wall_time = clock.wall_time();
    console << "  " << Loading::stage_name(state.stage) << " "
            << state.stage_factor << ": newton "
            << increment.n_newton_iterations << ", stick/slip/open "
            << increment.counts.n_stick << "/" << increment.counts.n_slip << "/"
            << increment.counts.n_open << ", residual "
            << increment.relative_residual << ", imbalance "
            << increment.balance.relative_imbalance << std::endl;
    // The output has its own timer: stop this one, so that the report
    // does not count the recording twice.
    scope.stop();
    if (observer.records())
      {
        dealii::TimerOutput::Scope output_scope(timer, "Contact: output");
        observer.record(responses, readable_solution);
      }
    result.increments.push_back(increment);
  }

  template <int dim>
  void
  ContactSolver<dim>::discard_attempt(const std::string     &attempt,
                                      const IncrementResult &increment)
  {
    n_failed_newton_iterations += increment.n_newton_iterations;
    console << "  failed: " << attempt << std::endl;
    current_solution = committed_solution;
    working_history  = committed_history;
    formulation->discard();
  }

  template <int dim>
  void
  ContactSolver<dim>::add_statistics(SolveResult &result) const
  {
    result.wall_times =
      timer.get_summary_data(dealii::TimerOutput::total_wall_time);
    result.n_linear_solves                      = n_linear_solves;
    result.n_failed_newton_iterations           = n_failed_newton_iterations;
    const Solver::SystemSolverStatistics linear = linear_solver->statistics();
    if (linear.iterative)
      {
        result.n_amg_setups            = linear.n_amg_setups;
        result.n_amg_krylov_iterations = linear.n_amg_krylov_iterations;
      }
    if (linear.direct)
      {
        result.n_factorizations         = linear.n_factorizations;
        result.n_krylov_iterations      = linear.n_krylov_iterations;
        result.n_solves_above_tolerance = linear.n_solves_above_tolerance;
      }
  }

  template <int dim>
  const dealii::TrilinosWrappers::MPI::Vector &
  ContactSolver<dim>::solution() const
  {
    return committed_solution;
  }

  template <int dim>
  const Fem::FeSpace<dim> &
  ContactSolver<dim>::space() const
  {
    return fe_space;
  }

  template <int dim>
  const std::vector<ContactNode<dim>> &
  ContactSolver<dim>::contact_nodes() const
  {
    return nodes;
  }

  template <int dim>
  std::vector<JointResponse<dim>>
  ContactSolver<dim>::responses_at_solution() const
  {
    return committed_responses;
  }

  template <int dim>
  const ContactProblem<dim> &
  ContactSolver<dim>::contact_problem() const
  {
    return problem;
  }

  template <int dim>
  const dealii::IndexSet &
  ContactSolver<dim>::supported_dofs() const
  {
    return dirichlet_dofs;
  }

  template class ContactSolver<2>;
  template class ContactSolver<3>;
} // namespace FloorBlock::Contact
