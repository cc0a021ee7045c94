#pragma once

#include <contact/active_set.h>
#include <contact/contact_formulation.h>
#include <contact/contact_node.h>
#include <contact/contact_problem.h>
#include <contact/increment_observer.h>
#include <contact/joint_law.h>
#include <contact/newton_driver.h>
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
   * the joints' part of the Newton system and the starts of an increment
   * from a ContactFormulation (CompliantFormulation, ExactFormulation),
   * the pair forces from assemble_contact,
   * the iteration from solve_newton, the linear algebra from
   * Solver::SystemSolver, the stages, increments and cutbacks from
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
    /** Wall times and solve counters of the run so far. */
    void
    add_statistics(SolveResult &result) const;
    /**
     * One increment of the load path through the formulation's starts
     * (ContactFormulation::solve_increment).
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
    /** The Newton matrix and residual at the current iterate. */
    NewtonIterate
    assemble_iterate(const Loading::LoadFactors &factors);
    /** The Newton update at the current iterate. */
    bool
    solve_update(const double forcing, std::string &message);
    /** Every pair's law at the current iterate. */
    std::vector<JointResponse<dim>>
    responses_at_iterate();
    double
    load_norm(const Loading::LoadFactors &factors);
    /** Sets the rigid obstacles' displacements for the uplift factor. */
    void
    move_obstacles(const double uplift_factor);

    const ContactProblem<dim>         problem;
    const ContactSolverSettings       settings;
    const Fem::FeSpace<dim>           fe_space;
    std::vector<ContactNode<dim>>     nodes;
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
    /** How the joints enter the Newton system: compliant or exact. */
    std::unique_ptr<ContactFormulation<dim>> formulation;
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
