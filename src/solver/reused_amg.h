#pragma once

#include <solver/linear_solver.h>
#include <solver/near_null_space.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_MultiVector.h>

#include <memory>
#include <vector>

namespace FloorBlock::Solver
{
  /** @brief Counters of a ReusedAmg (for reports and tests). */
  struct AmgStatistics
  {
    unsigned int n_solves = 0;
    /** ML hierarchies built (each costs about ten GMRES iterations). */
    unsigned int n_setups = 0;
    /** GMRES iterations of all solves, including abandoned attempts. */
    unsigned int n_krylov_iterations = 0;
  };

  /**
   * @brief GMRES preconditioned by an ML AMG hierarchy that is kept from
   * one matrix to the next while it still works.
   *
   * The iterative counterpart of ReusedFactorization. Between two Newton
   * iterations of a contact solve only the joint pairs whose state
   * changed alter the matrix; the bulk stiffness, which is what smoothed
   * aggregation resolves, is the same. A hierarchy built on an earlier
   * matrix stays nearly as good a preconditioner, and with inexact Newton
   * solves (a few GMRES iterations each) building it is most of a solve's
   * cost. A solve on the kept hierarchy may take at most
   * reuse_allowance times the iterations per decade of residual
   * reduction that the last fresh hierarchy needed; beyond that the
   * matrix gets a new hierarchy and the solve starts again. Either way
   * the answer meets the same residual, so reuse changes cost, not
   * results.
   */
  class ReusedAmg
  {
  public:
    /**
     * @param[in] settings GMRES tolerance and iteration cap.
     * @param[in] null_space Near-null space for ML over the locally owned
     *   rows of every matrix this solver sees (Fem::rigid_body_modes).
     */
    ReusedAmg(const LinearSolverSettings &settings,
              const NearNullSpace        &null_space);

    /**
     * @brief Solves matrix x = rhs to the relative residual
     * max(forcing, LinearSolverSettings::relative_tolerance).
     * @param[in] matrix System matrix (same sparsity every call).
     * @param[in] rhs Right-hand side.
     * @param[in,out] solution Result; unchanged on failure.
     * @param[in] forcing Relative residual the caller needs (-).
     */
    LinearSolveInfo
    solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
          const dealii::TrilinosWrappers::MPI::Vector  &rhs,
          dealii::TrilinosWrappers::MPI::Vector        &solution,
          double                                        forcing);

    const AmgStatistics &
    statistics() const;

    /**
     * A kept hierarchy may need this many times the iterations per
     * decade of the last fresh one before it is rebuilt (-): a setup
     * costs about as much as ten iterations, so a slightly slower
     * preconditioner that saves it still wins.
     */
    static constexpr double reuse_allowance = 1.5;

  private:
    void
    build(const dealii::TrilinosWrappers::SparseMatrix &matrix);

    /** GMRES with the current hierarchy; false if it hit @p max_iterations. */
    bool
    gmres(const dealii::TrilinosWrappers::SparseMatrix &matrix,
          const dealii::TrilinosWrappers::MPI::Vector  &rhs,
          double                                        relative_tolerance,
          unsigned int                                  max_iterations,
          dealii::TrilinosWrappers::MPI::Vector        &trial,
          LinearSolveInfo                              &info);

    const LinearSolverSettings settings;
    const NearNullSpace        null_space;
    /** The modes as ML reads them (column-major), built with the first
     * hierarchy. */
    std::unique_ptr<Epetra_MultiVector>       ml_null_space;
    dealii::TrilinosWrappers::PreconditionAMG preconditioner;
    bool                                      has_hierarchy = false;
    /** GMRES iterations per decade of reduction on the last fresh hierarchy. */
    double        fresh_iterations_per_decade = 0.;
    AmgStatistics counters;
  };
} // namespace FloorBlock::Solver
