#pragma once

#include <contact/active_set.h>
#include <contact/contact_node.h>
#include <contact/contact_problem.h>
#include <contact/exact_contact.h>
#include <contact/increment_observer.h>
#include <contact/joint_law.h>
#include <contact/results.h>
#include <fem/elastic_assembly.h>
#include <fem/fe_space.h>
#include <fem/stored_elastic_system.h>
#include <loading/load_path.h>
#include <solver/system_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief Quasi-static frictional multi-body contact, 2D plane strain
   * (dim = 2) or 3D (dim = 3; the compliant law also on a mesh
   * distributed over processes): follows the loading path
   * gravity -> support pressure -> floor uplift in increments, each a
   * converged equilibrium, with automatic cutback.
   *
   * Orchestration only: the bulk comes from Fem::assemble_elastic_system,
   * the joints from CoulombJoint through evaluate_contact/assemble_contact,
   * the iteration from solve_newton, the linear algebra from
   * Solver::solve_linear_system, the stages, increments and cutbacks from
   * Loading::follow_load_path; each converged increment goes to the
   * IncrementObserver given to run(), which reports and writes it.
   */
  template <int dim>
  class ContactSolver
  {
  public:
    /**
     * @param[in] triangulation Mesh with the agreed material and boundary
     *   ids; must outlive the solver.
     * @param[in] problem Physics and loading path.
     * @param[in] settings Numerics.
     * Throws InputError if a joint's sides do not match or a material has
     * no law.
     */
    ContactSolver(const dealii::Triangulation<dim> &triangulation,
                  const ContactProblem<dim>        &problem,
                  const ContactSolverSettings      &settings);

    /**
     * @brief Runs all stages.
     * @param[in,out] observer Describes every converged increment (its
     *   joint tables) and may record it.
     * @return Every converged increment as described by @p observer.
     * Throws ContactSolveFailure if an increment fails after all cutbacks;
     * solution() then holds the last converged state and the exception's
     * partial_result everything up to the failure.
     */
    SolveResult
    run(IncrementObserver<dim> &observer);

    /** @brief Displacement of the last converged increment (m). */
    const dealii::TrilinosWrappers::MPI::Vector &
    solution() const;

    const Fem::FeSpace<dim> &
    space() const;

    const std::vector<ContactNode<dim>> &
    contact_nodes() const;

    /** @brief The problem solved (a copy of the constructor's). */
    const ContactProblem<dim> &
    contact_problem() const;

    /** @brief The DoFs held by the supports. */
    const dealii::IndexSet &
    supported_dofs() const;

    /** @brief Joint law evaluations at solution(); empty before the first converged increment. */
    std::vector<JointResponse<dim>>
    responses_at_solution() const;

  private:
    void
    setup_contact();
    /** Wall times and solve counters of the run so far. */
    void
    add_statistics(SolveResult &result) const;
    /**
     * One increment of the load path: from the extrapolated state (if the
     * predictor applies), else or then from the last converged state, and
     * for the exact law then from a penalty start, and for the exact law
     * all of these again with the complementarity parameters a tenth;
     * each start is tried only when the one before failed.
     */
    bool
    solve_increment(const Loading::LoadState           &state,
                    const Loading::FailedStartRecorder &record_failed_start,
                    IncrementResult                    &increment,
                    std::string                        &failure_reason);
    /**
     * Has @p observer describe the converged @p increment, adds it to
     * @p result, makes it the committed state, then lets @p observer
     * record it.
     * @param[in] clock Started when the increment's first start began.
     */
    void
    commit_increment(const Loading::LoadState &state,
                     const dealii::Timer      &clock,
                     IncrementObserver<dim>   &observer,
                     IncrementResult          &increment,
                     SolveResult              &result);
    /** The starts of solve_increment() with the current parameters. */
    bool
    try_starts(const Loading::LoadState           &state,
               const Loading::FailedStartRecorder &record_failed_start,
               IncrementResult                    &increment,
               std::string                        &failure_reason);
    /** Back to the committed state after the failed @p attempt. */
    void
    discard_attempt(const std::string     &attempt,
                    const IncrementResult &increment);
    /** @p prediction: multiple of last_change added to the start (0: none). */
    bool
    solve_load_state(const Loading::LoadFactors &factors,
                     const double                prediction,
                     IncrementResult            &increment,
                     std::string                &failure_reason);
    /** Builds the multipliers' system (rigid-law pairs only). */
    void
    setup_exact_system();
    /** Every pair's law at the current iterate. */
    std::vector<JointResponse<dim>>
    responses_at_iterate();
    /** The Newton equations include the exact law's multipliers. */
    bool
    exact_equations() const;
    /**
     * The increment solved with the rigid-law pairs as springs of the
     * complementarity parameter's stiffness, then with the exact law
     * from that state (a fallback of the exact law).
     */
    bool
    solve_from_penalty_start(const Loading::LoadFactors &factors,
                             IncrementResult            &increment,
                             std::string                &failure_reason);
    dealii::AffineConstraints<double>
    constraints_at(const double uplift_factor);
    double
    load_norm(const Loading::LoadFactors &factors);
    /** Sets the rigid obstacles' displacements for the uplift factor. */
    void
    move_obstacles(const double uplift_factor);
    bool
    solve_linear(double forcing, std::string &message);
    void
    commit(const std::vector<JointResponse<dim>> &responses);

    const ContactProblem<dim>                       problem;
    const ContactSolverSettings                     settings;
    const Fem::FeSpace<dim>                         fe_space;
    std::vector<ContactNode<dim>>                   nodes;
    std::vector<std::unique_ptr<CoulombJoint<dim>>> joint_laws;
    std::vector<const CoulombJoint<dim> *>          pair_laws;
    /** Per pair: the exact law, empty for a compliant pair. */
    std::vector<std::optional<ExactPairLaw>> exact_laws;
    /**
     * Owns the springs of rigid-law pairs: kn = ks = c_n for the penalty
     * start, E/h for the pairs that yield at crosspoints.
     */
    std::vector<std::unique_ptr<CoulombJoint<dim>>> penalty_laws;
    /** pair_laws with the penalty springs in place of the exact law. */
    std::vector<const CoulombJoint<dim> *> penalty_pair_laws;
    /** Solving the penalty start (solve_from_penalty_start). */
    bool penalty_start = false;
    /** The exact law's equations; null when every pair is compliant. */
    std::unique_ptr<ExactContact<dim>> exact;
    /** Displacements and multipliers (exact law only). */
    dealii::TrilinosWrappers::SparsityPattern system_pattern;
    /** K and B^T, the constant part of the Newton matrix (exact law). */
    dealii::TrilinosWrappers::SparseMatrix base_matrix;
    dealii::TrilinosWrappers::MPI::Vector  system_residual;
    dealii::TrilinosWrappers::MPI::Vector  system_update;
    dealii::Vector<double>                 multiplier_update;
    dealii::Vector<double>                 multiplier_base;
    dealii::Vector<double>                 committed_multipliers;
    /**
     * The exact law's complementarity parameter per the configured one:
     * solve_increment() lowers it when every start of a load state fails
     * and keeps it lowered for the rest of the solve.
     */
    double                            complementarity_scale = 1.;
    std::vector<JointHistory<dim>>    committed_history;
    std::vector<JointHistory<dim>>    working_history;
    std::vector<JointResponse<dim>>   committed_responses;
    dealii::AffineConstraints<double> homogeneous_constraints;
    dealii::IndexSet                  dirichlet_dofs;
    /** Locally relevant DoFs and every pair's: what this process reads. */
    dealii::IndexSet                               readable_dofs;
    dealii::TrilinosWrappers::SparsityPattern      pattern;
    dealii::TrilinosWrappers::SparseMatrix         matrix;
    std::unique_ptr<Fem::StoredElasticSystem<dim>> bulk;
    /** Solves every Newton system, kept for the whole run. */
    std::unique_ptr<Solver::SystemSolver> linear_solver;
    unsigned int                          n_linear_solves            = 0;
    unsigned int                          n_failed_newton_iterations = 0;
    dealii::TrilinosWrappers::MPI::Vector current_solution;
    /**
     * current_solution where a process reads it: its locally relevant
     * DoFs and every pair's (ghosts on a distributed mesh).
     */
    dealii::TrilinosWrappers::MPI::Vector readable_solution;
    dealii::TrilinosWrappers::MPI::Vector committed_solution;
    dealii::TrilinosWrappers::MPI::Vector newton_base;
    dealii::TrilinosWrappers::MPI::Vector update;
    dealii::TrilinosWrappers::MPI::Vector residual;
    /** Displacement change of the last converged increment (m), which
     *  the predictor scales by LoadState::prediction_ratio. */
    dealii::TrilinosWrappers::MPI::Vector last_change;
    ActiveSet                             active_set;
    StateCounts                           last_iterate_counts;
    /** Appended to a failure message when compliant joints are very stiff. */
    std::string                stiffness_hint;
    dealii::ConditionalOStream console;
    dealii::TimerOutput        timer;
  };
} // namespace FloorBlock::Contact
