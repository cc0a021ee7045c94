#include <common/input_error.h>
#include <common/interrupt.h>
#include <contact/contact_assembly.h>
#include <contact/contact_solver.h>
#include <contact/crosspoints.h>
#include <contact/joint_pairing.h>
#include <contact/newton_driver.h>
#include <contact/swept_sections.h>
#include <contact/uplift.h>
#include <fem/dirichlet_constraints.h>
#include <fem/elastic_assembly.h>
#include <fem/rigid_body_modes.h>
#include <fem/sparsity.h>
#include <solver/system_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace FloorBlock::Contact
{
  namespace
  {
    /** kn h / E above which a failure suggests the rigid law (-). */
    constexpr double ill_conditioned_joint_ratio = 3.;

    template <int dim>
    std::vector<JointState>
    states_of(const std::vector<JointResponse<dim>> &responses)
    {
      std::vector<JointState> states;
      states.reserve(responses.size());
      for (const auto &response : responses)
        states.push_back(response.state);
      return states;
    }
  } // namespace

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
    const bool distributed = dealii::Utilities::MPI::n_mpi_processes(
                               fe_space.dof_handler().get_communicator()) > 1;
    dealii::TimerOutput::Scope                scope(timer, "Contact: setup");
    std::vector<Fem::DirichletCondition<dim>> zero_conditions;
    for (const auto &support : problem.supports)
      zero_conditions.push_back(
        {support.boundary_id,
         support.constrained_components,
         [](const dealii::Point<dim> &) { return dealii::Tensor<1, dim>(); }});
    homogeneous_constraints =
      Fem::make_constraints(fe_space, zero_conditions, true, dirichlet_dofs);
    // After the supports: a node they hold is ground for the crosspoints.
    setup_contact();
    readable_dofs = fe_space.locally_relevant_dofs();
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
    if (std::any_of(exact_laws.begin(), exact_laws.end(), [](const auto &law) {
          return law.has_value();
        }))
      {
        if (distributed)
          throw std::logic_error(
            "the exact (rigid) joint law runs on one process only");
        setup_exact_system();
      }
    linear_solver = std::make_unique<Solver::SystemSolver>(
      settings.linear,
      Solver::SystemDescription{fe_space.dof_handler().n_dofs(),
                                exact != nullptr},
      fe_space.dof_handler().get_communicator(),
      [this]() { return Fem::rigid_body_modes(fe_space); });
    const dealii::IndexSet &owned = fe_space.locally_owned_dofs();
    // The triangulation's communicator: MPI_COMM_SELF for a serial mesh,
    // so that every rank of a sweep solves its own case independently.
    const MPI_Comm communicator = fe_space.dof_handler().get_communicator();
    current_solution.reinit(owned, communicator);
    committed_solution.reinit(owned, communicator);
    newton_base.reinit(owned, communicator);
    update.reinit(owned, communicator);
    residual.reinit(owned, communicator);
    last_change.reinit(owned, communicator);
    readable_solution.reinit(owned, readable_dofs, communicator);
  }

  template <int dim>
  void
  ContactSolver<dim>::setup_contact()
  {
    double largest_modulus = 0.;
    for (const auto &entry : problem.model.laws)
      largest_modulus =
        std::max(largest_modulus, entry.second.youngs_modulus());
    // The pairs' scales are lengths along the joint line, as in 2D: in 3D
    // a pair's weight is an area, and the joint's contact ends run along
    // the face, resolved by the in-plane cells (swept_sections.h).
    const auto  &triangulation = fe_space.dof_handler().get_triangulation();
    const double smallest_cell = smallest_in_plane_cell(triangulation);
    for (unsigned int j = 0; j < problem.joints.size(); ++j)
      {
        const JointDefinition<dim> &joint = problem.joints[j];
        if (joint.obstacle_curvature != 0. &&
            (!(joint.obstacle_curvature > 0.) || !joint.against_rigid_plane ||
             joint.plane_moves_with_uplift))
          throw std::logic_error(
            "joint '" + joint.name +
            "': an obstacle curvature needs a fixed rigid plane and must be "
            "positive");
        if (joint.law == JointLawKind::compliant &&
            (!(joint.parameters.normal_stiffness > 0.) ||
             !(joint.parameters.shear_stiffness > 0.)))
          throw InputError("joint '" + joint.name +
                           "': compliant law needs kn > 0 and ks > 0 Pa/m");
        joint_laws.push_back(
          std::make_unique<CoulombJoint<dim>>(joint.parameters));
        const std::vector<ContactNode<dim>> joint_nodes =
          joint.against_rigid_plane ?
            pair_nodes_with_plane(fe_space,
                                  joint.side_a,
                                  joint.plane_point,
                                  joint.plane_normal,
                                  joint.obstacle_curvature,
                                  j) :
            pair_joint_nodes(fe_space, joint.side_a, joint.side_b, j);
        nodes.insert(nodes.end(), joint_nodes.begin(), joint_nodes.end());
      }
    std::vector<bool> joint_is_exact;
    for (const auto &joint : problem.joints)
      joint_is_exact.push_back(joint.law == JointLawKind::rigid);
    const std::vector<bool> yields_at_crosspoint =
      crosspoint_pairs(nodes, joint_is_exact, dirichlet_dofs);
    const unsigned int n_crosspoint_pairs =
      std::count(yields_at_crosspoint.begin(),
                 yields_at_crosspoint.end(),
                 true);
    if (n_crosspoint_pairs > 0)
      console << "  " << n_crosspoint_pairs
              << " rigid-law pairs at crosspoints follow springs of the "
                 "surface stiffness"
              << std::endl;

    const std::vector<double> pair_lengths =
      weights_along_joint(nodes,
                          problem.joints.size(),
                          face_length_of(triangulation));
    for (unsigned int p = 0; p < nodes.size(); ++p)
      {
        const ContactNode<dim>     &node  = nodes[p];
        const JointDefinition<dim> &joint = problem.joints[node.joint];
        if (joint.law == JointLawKind::compliant)
          {
            pair_laws.push_back(joint_laws[node.joint].get());
            penalty_pair_laws.push_back(pair_laws.back());
            exact_laws.emplace_back();
            continue;
          }
        // Exact law: the complementarity parameter per pair is a multiple
        // of the surface's own stiffness E / w, so that the multiplier and
        // gap terms of the augmented multipliers weigh alike at every pair
        // whatever its cell size. It changes the Newton iterates, never
        // the converged answer.
        const double length = std::max(pair_lengths[p], smallest_cell);
        ExactPairLaw law;
        law.surface_stiffness = largest_modulus / length;
        law.complementarity.friction_coefficient =
          std::tan(joint.parameters.friction_angle);
        law.complementarity.cohesion = joint.parameters.cohesion;
        law.complementarity.normal_parameter =
          settings.complementarity_factor * law.surface_stiffness;
        law.complementarity.tangential_parameter =
          law.complementarity.normal_parameter;
        JointConstants springs   = joint.parameters;
        springs.normal_stiffness = law.complementarity.normal_parameter;
        springs.shear_stiffness  = law.complementarity.tangential_parameter;
        springs.tensile_strength = 0.;
        if (yields_at_crosspoint[p])
          {
            // Springs of the surface stiffness E / h itself (not of the
            // complementarity parameter, which must not change a result).
            springs.normal_stiffness = law.surface_stiffness;
            springs.shear_stiffness  = law.surface_stiffness;
            penalty_laws.push_back(
              std::make_unique<CoulombJoint<dim>>(springs));
            pair_laws.push_back(penalty_laws.back().get());
            penalty_pair_laws.push_back(pair_laws.back());
            exact_laws.emplace_back();
            continue;
          }
        exact_laws.push_back(law);
        pair_laws.push_back(nullptr);
        penalty_laws.push_back(std::make_unique<CoulombJoint<dim>>(springs));
        penalty_pair_laws.push_back(penalty_laws.back().get());
      }
    committed_history.assign(nodes.size(), JointHistory<dim>());
    working_history = committed_history;

    // Compliant joints much stiffer than the cells they join make the
    // Newton matrix ill-conditioned and the contact set flip (bug 3 of
    // tests/scenarios/HARD_CASES.md: kn h / E = 9 cycles, 0.9 converges);
    // a failure then names the remedy.
    double stiffest = 0.;
    for (const auto &joint : problem.joints)
      if (joint.law == JointLawKind::compliant)
        stiffest = std::max({stiffest,
                             joint.parameters.normal_stiffness,
                             joint.parameters.shear_stiffness});
    const double ratio = stiffest * smallest_cell / largest_modulus;
    if (ratio > ill_conditioned_joint_ratio)
      {
        std::ostringstream hint;
        hint << "; note: the compliant joints are stiff against the "
                "blocks (kn h / E = "
             << ratio << " with h the smallest cell, " << smallest_cell
             << " m): use Joints/Law = rigid for joints this stiff";
        stiffness_hint = hint.str();
      }
  }

  template <int dim>
  void
  ContactSolver<dim>::setup_exact_system()
  {
    const unsigned int n_u = fe_space.dof_handler().n_dofs();
    exact                  = std::make_unique<ExactContact<dim>>(nodes,
                                                exact_laws,
                                                homogeneous_constraints,
                                                n_u);
    complementarity_scale  = 1.; // the configured parameter
    const unsigned int             n_total = n_u + exact->n_multipliers();
    dealii::DynamicSparsityPattern couplings(n_total, n_total);
    for (auto entry = pattern.begin(); entry != pattern.end(); ++entry)
      couplings.add(entry->row(), entry->column());
    exact->add_couplings(couplings);
    const MPI_Comm communicator = fe_space.dof_handler().get_communicator();
    const dealii::IndexSet all  = dealii::complete_index_set(n_total);
    system_pattern.reinit(all, all, couplings, communicator);
    system_pattern.compress();
    // K and the multipliers' forces B^T never change: stored once, copied
    // at every Newton iteration before the equations of the pairs are
    // added.
    base_matrix.reinit(system_pattern);
    const auto &stiffness = bulk->condensed_stiffness();
    for (auto entry = stiffness.begin(); entry != stiffness.end(); ++entry)
      base_matrix.set(entry->row(), entry->column(), entry->value());
    base_matrix.compress(dealii::VectorOperation::insert);
    exact->add_force_block(base_matrix);
    matrix.reinit(system_pattern);
    system_residual.reinit(all, communicator);
    system_update.reinit(all, communicator);
    multiplier_update.reinit(exact->n_multipliers());
    multiplier_base.reinit(exact->n_multipliers());
    committed_multipliers.reinit(exact->n_multipliers());
    if (exact->n_fixed_directions() > 0)
      console << "  " << exact->n_fixed_directions()
              << " rigid-law pair directions held on both sides: their "
                 "tractions are support reactions"
              << std::endl;
  }

  template <int dim>
  dealii::AffineConstraints<double>
  ContactSolver<dim>::constraints_at(const double uplift_factor)
  {
    std::vector<Fem::DirichletCondition<dim>> conditions;
    const UpliftSettings                      uplift = problem.uplift;
    for (const auto &support : problem.supports)
      {
        const bool moves = support.moves_with_uplift;
        conditions.push_back(
          {support.boundary_id,
           support.constrained_components,
           [uplift, uplift_factor, moves](const dealii::Point<dim> &point) {
             return moves ? uplift_displacement(uplift, uplift_factor, point) :
                            dealii::Tensor<1, dim>();
           }});
      }
    return Fem::make_constraints(fe_space, conditions, false, dirichlet_dofs);
  }

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
  bool
  ContactSolver<dim>::solve_linear(const double forcing, std::string &message)
  {
    ++n_linear_solves;
    if (exact_equations())
      {
        // Multipliers make the system a saddle point: direct solver only.
        dealii::TrilinosWrappers::MPI::Vector right_hand_side(system_residual);
        right_hand_side *= -1.;
        system_update = 0.;
        const Solver::LinearSolveInfo info =
          linear_solver->solve(matrix, right_hand_side, system_update, 0.);
        message = info.message;
        if (!info.success)
          return false;
        const unsigned int n_u = update.size();
        std::copy(system_update.begin(),
                  system_update.begin() + n_u,
                  update.begin());
        std::copy(system_update.begin() + n_u,
                  system_update.end(),
                  multiplier_update.begin());
        return true;
      }
    dealii::TrilinosWrappers::MPI::Vector right_hand_side(residual);
    right_hand_side *= -1.;
    update = 0.;
    const Solver::LinearSolveInfo info =
      linear_solver->solve(matrix, right_hand_side, update, forcing);
    message = info.message;
    return info.success;
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
      return constraints_at(factors.uplift);
    }();
    constraints.distribute(current_solution);
    move_obstacles(factors.uplift);
    double reference_load = load_norm(factors);

    NewtonCallbacks callbacks;
    callbacks.assemble = [&]() {
      dealii::TimerOutput::Scope            scope(timer, "Contact: assemble");
      const std::vector<JointResponse<dim>> responses = responses_at_iterate();
      matrix.copy_from(exact_equations() ? base_matrix :
                                           bulk->condensed_stiffness());
      bulk->residual(current_solution,
                     factors.gravity,
                     factors.support,
                     residual);
      assemble_contact(
        nodes, responses, homogeneous_constraints, &matrix, &residual);
      if (exact_equations())
        {
          std::copy(residual.begin(), residual.end(), system_residual.begin());
          std::fill(system_residual.begin() + residual.size(),
                    system_residual.end(),
                    0.);
          exact->assemble_equations(matrix, system_residual);
        }
      active_set.update(states_of(responses));
      NewtonIterate iterate;
      iterate.residual_norm =
        exact_equations() ? system_residual.l2_norm() : residual.l2_norm();
      iterate.set_signature = active_set.signature();
      iterate.counts        = active_set.counts();
      last_iterate_counts   = iterate.counts;
      console << "    residual " << iterate.residual_norm
              << " N, stick/slip/open " << iterate.counts.n_stick << "/"
              << iterate.counts.n_slip << "/" << iterate.counts.n_open
              << std::endl;
      return iterate;
    };
    callbacks.solve_update = [&](const double forcing, std::string &message) {
      dealii::TimerOutput::Scope scope(timer, "Contact: linear solve");
      if (!solve_linear(forcing, message))
        return false;
      homogeneous_constraints.distribute(update);
      newton_base = current_solution;
      if (exact_equations())
        multiplier_base = exact->multipliers();
      return true;
    };
    callbacks.set_step = [&](const double step) {
      current_solution = newton_base;
      current_solution.add(step, update);
      if (exact_equations())
        {
          exact->multipliers() = multiplier_base;
          exact->multipliers().add(step, multiplier_update);
        }
    };
    callbacks.round_off_floor = [&]() {
      const double bulk_floor = bulk->round_off_floor(current_solution,
                                                      factors.gravity,
                                                      factors.support);
      const double contact_floor =
        exact_equations() ? exact->round_off_floor(current_solution) : 0.;
      return std::hypot(bulk_floor, contact_floor);
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
    else if (exact_equations())
      exact->zero_open_multipliers();
    return report.converged;
  }

  template <int dim>
  std::vector<JointResponse<dim>>
  ContactSolver<dim>::responses_at_iterate()
  {
    readable_solution = current_solution;
    std::vector<JointResponse<dim>> responses =
      evaluate_contact(nodes,
                       penalty_start ? penalty_pair_laws : pair_laws,
                       working_history,
                       readable_solution);
    if (exact_equations())
      exact->evaluate(current_solution, working_history, responses);
    return responses;
  }

  template <int dim>
  bool
  ContactSolver<dim>::exact_equations() const
  {
    return exact && !penalty_start;
  }

  template <int dim>
  bool
  ContactSolver<dim>::solve_from_penalty_start(
    const Loading::LoadFactors &factors,
    IncrementResult            &increment,
    std::string                &failure_reason)
  {
    // The exact law's first iterate ties every pair (stick at g = 0,
    // lambda = 0); from there a block can reach an iterate held by
    // slipping pairs alone, a singular Newton matrix (six-block scene,
    // first increment: a block next to the face lifted off its bedding).
    // Springs of the complementarity parameter's stiffness let the
    // blocks settle; their state and tractions start the exact Newton.
    penalty_start = true;
    IncrementResult penalty_increment;
    const bool      settled =
      solve_load_state(factors, 0., penalty_increment, failure_reason);
    if (settled)
      exact->set_multipliers(responses_at_iterate());
    penalty_start = false;
    if (!settled)
      {
        failure_reason = "penalty start: " + failure_reason;
        return false;
      }
    const bool solved =
      solve_load_state(factors, 0., increment, failure_reason);
    increment.n_newton_iterations += penalty_increment.n_newton_iterations;
    increment.started_from_penalty = true;
    return solved;
  }

  template <int dim>
  void
  ContactSolver<dim>::commit(const std::vector<JointResponse<dim>> &responses)
  {
    committed_solution  = current_solution;
    committed_responses = responses;
    if (exact)
      committed_multipliers = exact->multipliers();
    for (unsigned int p = 0; p < nodes.size(); ++p)
      {
        const JointResponse<dim> &response = responses[p];
        JointHistory<dim>        &history  = committed_history[p];
        history.tangential_base            = response.tangential_traction;
        history.reference_slip             = response.slip;
        // UDEC convention: cohesion and tensile strength are lost for good
        // once the pair slips or opens.
        history.intact = history.intact && response.state == JointState::stick;
      }
    working_history = committed_history;
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
    if (exact)
      {
        exact->multipliers()  = 0.;
        committed_multipliers = exact->multipliers();
      }

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
    if (try_starts(state, record_failed_start, increment, failure_reason))
      return true;
    if (!exact)
      return false;
    // Whether the semi-smooth Newton cycles between active sets depends
    // on the complementarity parameter, the answer does not: the default
    // scene with vertical friction 80 deg cycles in its support stage at
    // the factor 0.1 from every start and converges at 0.01; the
    // three-block scene fails at 100 and converges at 10. So before a
    // cutback the starts are tried once more with the parameter a tenth.
    // The multipliers are rescaled both ways (they keep their tractions),
    // and so is the force block B^T (w c_n) of the stored matrix. The
    // penalty start keeps its springs of the configured parameter: they
    // only make a starting point.
    // A rescued state keeps the smaller parameter for the rest of the
    // solve: restoring it let the three-block scene at 100 cycle again in
    // its uplift stage and fail there after all cutbacks on one machine
    // (while it passed on another: which state cycles is a matter of
    // round-off). At most two reductions (a hundredth of the configured
    // value), so a state that fails for another reason ends in cutbacks.
    constexpr double smaller        = 0.1;
    constexpr double smallest_scale = 0.01 * (1. - 1e-12);
    if (complementarity_scale * smaller < smallest_scale)
      return false;
    record_failed_start("every start", failure_reason);
    const auto scale_complementarity = [&](const double factor) {
      exact->scale_complementarity(factor);
      exact->add_force_block(base_matrix, 1. - 1. / factor);
      committed_multipliers /= factor;
    };
    scale_complementarity(smaller);
    if (try_starts(state, record_failed_start, increment, failure_reason))
      {
        complementarity_scale *= smaller;
        return true;
      }
    scale_complementarity(1. / smaller);
    failure_reason = "complementarity parameter a tenth: " + failure_reason;
    return false;
  }

  template <int dim>
  bool
  ContactSolver<dim>::try_starts(
    const Loading::LoadState           &state,
    const Loading::FailedStartRecorder &record_failed_start,
    IncrementResult                    &increment,
    std::string                        &failure_reason)
  {
    increment = IncrementResult();
    const double prediction =
      settings.extrapolate_increments ? state.prediction_ratio : 0.;
    if (prediction > 0.)
      {
        if (solve_load_state(
              state.factors, prediction, increment, failure_reason))
          return true;
        // The extrapolated start can lie where a very stiff joint law
        // makes the active set cycle (kn = 1e14 Pa/m, two-block test);
        // the plain start is tried before any cutback, so a start the
        // predictor spoils costs a retry, not a cutback.
        record_failed_start("extrapolated start", failure_reason);
        increment = IncrementResult();
      }
    if (solve_load_state(state.factors, 0., increment, failure_reason))
      return true;
    if (!exact)
      return false;
    record_failed_start("exact law from the last state", failure_reason);
    increment = IncrementResult();
    return solve_from_penalty_start(state.factors, increment, failure_reason);
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
    increment.complementarity_factor                = complementarity_scale;
    increment.counts = count_states(states_of(responses));
    // readable_solution holds current_solution: responses_at_iterate().
    observer.describe(state.factors, responses, readable_solution, increment);
    last_change = current_solution;
    last_change -= committed_solution;
    commit(responses);
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
    if (exact)
      exact->multipliers() = committed_multipliers;
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
