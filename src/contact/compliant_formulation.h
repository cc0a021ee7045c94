#pragma once

#include <contact/contact_formulation.h>
#include <contact/joint_law.h>

#include <memory>
#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief Every pair follows springs: its joint's compliant law, or at a
   * crosspoint springs of the surface stiffness. The displacements are
   * the only unknowns; the starts are the plain ones (try_plain_starts).
   */
  template <int dim>
  class CompliantFormulation : public ContactFormulation<dim>
  {
  public:
    /**
     * @param[in] system The solver's pairs, constraints and bulk.
     * @param[in] owned_laws The laws @p pair_laws point to.
     * @param[in] pair_laws Every pair's law.
     */
    CompliantFormulation(
      const ContactSystem<dim>                         &system,
      std::vector<std::unique_ptr<CoulombJoint<dim>>> &&owned_laws,
      const std::vector<const CoulombJoint<dim> *>     &pair_laws);

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
    bool
    solve_increment(const Loading::LoadState           &state,
                    const Loading::FailedStartRecorder &record_failed_start,
                    const LoadStateStarts<dim>         &starts,
                    IncrementResult                    &increment,
                    std::string &failure_reason) override;

  private:
    const ContactSystem<dim>                        system;
    std::vector<std::unique_ptr<CoulombJoint<dim>>> owned_laws;
    std::vector<const CoulombJoint<dim> *>          pair_laws;
  };

  /**
   * @brief Solves the displacement system for @p update: matrix update =
   * -residual (both formulations' system without multipliers).
   */
  Solver::LinearSolveInfo
  solve_displacement_system(
    Solver::SystemSolver                         &linear_solver,
    const dealii::TrilinosWrappers::SparseMatrix &matrix,
    const dealii::TrilinosWrappers::MPI::Vector  &residual,
    const double                                  forcing,
    dealii::TrilinosWrappers::MPI::Vector        &update);
} // namespace FloorBlock::Contact
