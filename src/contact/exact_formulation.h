#pragma once

#include <contact/contact_formulation.h>
#include <contact/exact_contact.h>
#include <contact/joint_law.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <optional>
#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief Rigid-law pairs as exact contact: their multipliers are
   * unknowns of the Newton system beside the displacements
   * (ExactContact); compliant and crosspoint pairs follow springs.
   *
   * Its starts, after the plain ones: a penalty start (the rigid-law
   * pairs as springs of the complementarity parameter's stiffness, their
   * state and tractions then starting the exact Newton), and when every
   * start fails all of them again with the complementarity parameter a
   * tenth.
   */
  template <int dim>
  class ExactFormulation : public ContactFormulation<dim>
  {
  public:
    /**
     * @param[in] system The solver's pairs, constraints and bulk.
     * @param[in] owned_laws The laws the pair laws point to.
     * @param[in] pair_laws Every pair's law; null for an exact pair.
     * @param[in] penalty_pair_laws pair_laws with springs of the
     *   complementarity parameter's stiffness for the exact pairs.
     * @param[in] exact_laws Per pair the exact law, empty for a spring.
     * @param[in] pattern Sparsity of the displacement system.
     * @param[in,out] matrix The solver's Newton matrix: given the pattern
     *   of displacements and multipliers.
     * @param[in] console Where set-up notes go.
     */
    ExactFormulation(
      const ContactSystem<dim>                         &system,
      std::vector<std::unique_ptr<CoulombJoint<dim>>> &&owned_laws,
      const std::vector<const CoulombJoint<dim> *>     &pair_laws,
      const std::vector<const CoulombJoint<dim> *>     &penalty_pair_laws,
      const std::vector<std::optional<ExactPairLaw>>   &exact_laws,
      const dealii::TrilinosWrappers::SparsityPattern  &pattern,
      dealii::TrilinosWrappers::SparseMatrix           &matrix,
      dealii::ConditionalOStream                       &console);

    void
    reset() override;
    std::vector<JointResponse<dim>>
    evaluate(const dealii::TrilinosWrappers::MPI::Vector &solution,
             const dealii::TrilinosWrappers::MPI::Vector &readable_solution,
             const std::vector<JointHistory<dim>>        &histories) override;
    const dealii::TrilinosWrappers::SparseMatrix &
    constant_matrix() const override;
    double
    add_equations(
      dealii::TrilinosWrappers::SparseMatrix      &matrix,
      const dealii::TrilinosWrappers::MPI::Vector &residual) override;
    Solver::LinearSolveInfo
    solve(Solver::SystemSolver                         &linear_solver,
          const dealii::TrilinosWrappers::SparseMatrix &matrix,
          const dealii::TrilinosWrappers::MPI::Vector  &residual,
          const double                                  forcing,
          dealii::TrilinosWrappers::MPI::Vector        &update) override;
    void
    keep_newton_base() override;
    void
    set_step(const double step) override;
    double
    round_off_floor(
      const dealii::TrilinosWrappers::MPI::Vector &solution) const override;
    void
    converged() override;
    void
    commit() override;
    void
    discard() override;
    double
    complementarity_factor() const override;
    /**
     * The plain starts, then the penalty start; when all fail, all of
     * them again with the complementarity parameter a tenth.
     */
    bool
    solve_increment(const Loading::LoadState           &state,
                    const Loading::FailedStartRecorder &record_failed_start,
                    const LoadStateStarts<dim>         &starts,
                    IncrementResult                    &increment,
                    std::string &failure_reason) override;

  private:
    /** The starts of solve_increment() with the current parameters. */
    bool
    try_starts(const Loading::LoadState           &state,
               const Loading::FailedStartRecorder &record_failed_start,
               const LoadStateStarts<dim>         &starts,
               IncrementResult                    &increment,
               std::string                        &failure_reason);
    /**
     * The increment solved with the rigid-law pairs as springs of the
     * complementarity parameter's stiffness, then with the exact law
     * from that state.
     */
    bool
    solve_from_penalty_start(const Loading::LoadFactors &factors,
                             const LoadStateStarts<dim> &starts,
                             IncrementResult            &increment,
                             std::string                &failure_reason);
    /** Multiplies the complementarity parameters by @p factor. */
    void
    scale_complementarity(const double factor);
    /** The Newton equations include the multipliers (not penalty start). */
    bool
    equations() const;

    const ContactSystem<dim>                        system;
    std::vector<std::unique_ptr<CoulombJoint<dim>>> owned_laws;
    std::vector<const CoulombJoint<dim> *>          pair_laws;
    /** pair_laws with the penalty springs in place of the exact law. */
    std::vector<const CoulombJoint<dim> *> penalty_pair_laws;
    /** Per pair the exact law (ExactContact keeps a reference). */
    const std::vector<std::optional<ExactPairLaw>> exact_laws;
    /** Solving the penalty start (solve_from_penalty_start). */
    bool                               penalty_start = false;
    std::unique_ptr<ExactContact<dim>> exact;
    /** Displacements and multipliers. */
    dealii::TrilinosWrappers::SparsityPattern system_pattern;
    /** K and B^T, the constant part of the Newton matrix. */
    dealii::TrilinosWrappers::SparseMatrix base_matrix;
    dealii::TrilinosWrappers::MPI::Vector  system_residual;
    dealii::TrilinosWrappers::MPI::Vector  system_update;
    dealii::Vector<double>                 multiplier_update;
    dealii::Vector<double>                 multiplier_base;
    dealii::Vector<double>                 committed_multipliers;
    /**
     * The complementarity parameter per the configured one:
     * solve_increment() lowers it when every start of a load state fails
     * and keeps it lowered for the rest of the solve.
     */
    double complementarity_scale = 1.;
  };
} // namespace FloorBlock::Contact
