#pragma once

#include <contact/contact_node.h>
#include <contact/contact_setup.h>
#include <contact/joint_law.h>
#include <contact/results.h>
#include <fem/stored_elastic_system.h>
#include <loading/load_path.h>
#include <solver/system_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief The parts of ContactSolver's Newton system that a formulation
   * reads: the pairs, the homogeneous constraints and the bulk. The solver
   * owns them; they outlive the formulation.
   */
  template <int dim>
  struct ContactSystem
  {
    const std::vector<ContactNode<dim>>     &nodes;
    const dealii::AffineConstraints<double> &constraints;
    const Fem::StoredElasticSystem<dim>     &bulk;
  };

  /**
   * @brief How ContactSolver solves one load state from one start, as a
   * formulation's start cascade sees it.
   */
  template <int dim>
  struct LoadStateStarts
  {
    /**
     * Newton from the last converged state plus @p prediction times its
     * last change (0: none); false with the reason on failure.
     */
    std::function<bool(const Loading::LoadFactors &factors,
                       const double                prediction,
                       IncrementResult            &increment,
                       std::string                &failure_reason)>
      solve;
    /** Every pair's law at the current iterate. */
    std::function<std::vector<JointResponse<dim>>()> responses_at_iterate;
    /** Multiple of the last change the extrapolated start adds (0: none). */
    double prediction = 0.;
  };

  /**
   * @brief A contact formulation: how the joints enter the Newton system
   * of ContactSolver, with its own state and its own start cascade.
   *
   * Two siblings implement it: CompliantFormulation (every pair a joint
   * spring or a crosspoint spring; the displacements are the unknowns)
   * and ExactFormulation (rigid-law pairs with multipliers appended to the
   * displacements). The solver assembles the bulk and the pair forces,
   * then asks the formulation for the rest.
   */
  template <int dim>
  class ContactFormulation
  {
  public:
    virtual ~ContactFormulation() = default;

    /** @brief Back to the unloaded state (multipliers zero). */
    virtual void
    reset() = 0;

    /**
     * @brief Every pair's law at the iterate.
     * @param[in] solution The iterate (m), locally owned.
     * @param[in] readable_solution The iterate where this process reads
     *   it (its locally relevant DoFs and every pair's).
     * @param[in] histories Every pair's converged history.
     */
    virtual std::vector<JointResponse<dim>>
    evaluate(const dealii::TrilinosWrappers::MPI::Vector &solution,
             const dealii::TrilinosWrappers::MPI::Vector &readable_solution,
             const std::vector<JointHistory<dim>>        &histories) = 0;

    /** @brief The constant part of the Newton matrix. */
    virtual const dealii::TrilinosWrappers::SparseMatrix &
    constant_matrix() const = 0;

    /**
     * @brief Completes the Newton system whose displacement residual (the
     * bulk and pair forces) is @p residual.
     * @return The norm of the whole residual (N).
     */
    virtual double
    add_equations(dealii::TrilinosWrappers::SparseMatrix      &matrix,
                  const dealii::TrilinosWrappers::MPI::Vector &residual) = 0;

    /**
     * @brief Solves the Newton system for the displacement @p update
     * (and the formulation's own unknowns).
     */
    virtual Solver::LinearSolveInfo
    solve(Solver::SystemSolver                         &linear_solver,
          const dealii::TrilinosWrappers::SparseMatrix &matrix,
          const dealii::TrilinosWrappers::MPI::Vector  &residual,
          const double                                  forcing,
          dealii::TrilinosWrappers::MPI::Vector        &update) = 0;

    /** @brief Keeps the own unknowns as the base of the line search. */
    virtual void
    keep_newton_base() = 0;

    /** @brief Own unknowns = base + @p step times their update. */
    virtual void
    set_step(const double step) = 0;

    /** @brief Round-off floor of the own equations (N). */
    virtual double
    round_off_floor(
      const dealii::TrilinosWrappers::MPI::Vector &solution) const = 0;

    /** @brief Called when Newton has converged a load state. */
    virtual void
    converged() = 0;

    /** @brief Makes the own unknowns the committed state. */
    virtual void
    commit() = 0;

    /** @brief Back to the committed own unknowns. */
    virtual void
    discard() = 0;

    /**
     * @brief The complementarity parameter per the configured one (1 for
     * a formulation without multipliers).
     */
    virtual double
    complementarity_factor() const = 0;

    /**
     * @brief Solves one load state through the formulation's starts, each
     * tried only when the one before failed.
     */
    virtual bool
    solve_increment(const Loading::LoadState           &state,
                    const Loading::FailedStartRecorder &record_failed_start,
                    const LoadStateStarts<dim>         &starts,
                    IncrementResult                    &increment,
                    std::string                        &failure_reason) = 0;
  };

  /**
   * @brief The starts every formulation tries first: from the extrapolated
   * state (if @p starts has a prediction), else or then from the last
   * converged state.
   */
  template <int dim>
  bool
  try_plain_starts(const Loading::LoadState           &state,
                   const Loading::FailedStartRecorder &record_failed_start,
                   const LoadStateStarts<dim>         &starts,
                   IncrementResult                    &increment,
                   std::string                        &failure_reason);

  /**
   * @brief The formulation of @p laws: ExactFormulation if some pair has
   * the exact law, else CompliantFormulation.
   * @param[in,out] laws Gives up its owned laws to the formulation.
   * @param[in] pattern Sparsity of the displacement system.
   * @param[in,out] matrix The solver's Newton matrix (the exact
   *   formulation gives it the pattern with the multipliers).
   * @param[in] console Where set-up notes go.
   */
  template <int dim>
  std::unique_ptr<ContactFormulation<dim>>
  make_contact_formulation(
    const ContactSystem<dim>                        &system,
    PairLaws<dim>                                   &laws,
    const dealii::TrilinosWrappers::SparsityPattern &pattern,
    dealii::TrilinosWrappers::SparseMatrix          &matrix,
    dealii::ConditionalOStream                      &console);
} // namespace FloorBlock::Contact
