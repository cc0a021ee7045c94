#pragma once

#include <solver/linear_solver.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace FloorBlock::Solver
{
  /** @brief Counters of a ReusedFactorization (for reports and tests). */
  struct ReuseStatistics
  {
    unsigned int n_solves         = 0;
    unsigned int n_factorizations = 0;
    /** Solves that converged on an older factorisation. */
    unsigned int n_reused = 0;
    /** GMRES iterations of all solves, including abandoned attempts. */
    unsigned int n_krylov_iterations = 0;
    /**
     * Direct solutions accepted although their residual stays above the
     * tolerance (ill-conditioned matrix: fresh factors and GMRES on them
     * could not reach it either).
     */
    unsigned int n_accepted_above_tolerance = 0;
  };

  class UmfpackFactors;

  /**
   * @brief Sparse direct solver (Amesos KLU or UMFPACK, see
   * LinearSolverSettings::direct_solver) that keeps its LU factors and
   * tries them on the next matrix first.
   *
   * Between two Newton iterations of a contact solve only the joint
   * pairs whose state changed alter the matrix: a low-rank change. The
   * factors of an earlier matrix are then an almost exact preconditioner,
   * and right-preconditioned GMRES converges in a few iterations, each a
   * pair of triangular solves (0.5 ms on the default mesh) instead of a
   * numeric factorisation (14 ms). When GMRES
   * does not reach the tolerance within LinearSolverSettings::
   * max_reuse_iterations the matrix is factorised afresh (symbolic
   * analysis reused: the pattern never changes) and solved with the new
   * factors. Either way the answer meets the same relative residual
   * LinearSolverSettings::relative_tolerance, so reuse changes cost, not
   * results; only on a matrix so ill-conditioned that fresh factors miss
   * it too is the plain direct solution accepted, flagged by
   * ReuseStatistics::n_accepted_above_tolerance.
   */
  class ReusedFactorization
  {
  public:
    explicit ReusedFactorization(const LinearSolverSettings &settings);
    ~ReusedFactorization();

    /**
     * @brief Solves matrix x = rhs.
     * @param[in] matrix System matrix; a new sparsity pattern restarts the
     *   factorisation (the reuse test compares rows of equal patterns).
     * @param[in] rhs Right-hand side.
     * @param[in,out] solution Result; unchanged on failure.
     * @return Success, iterations and a message on failure; never throws
     *   for a singular matrix and never leaves NaN in @p solution.
     */
    LinearSolveInfo
    solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
          const dealii::TrilinosWrappers::MPI::Vector  &rhs,
          dealii::TrilinosWrappers::MPI::Vector        &solution);

    const ReuseStatistics &
    statistics() const;

    /**
     * @brief Applies the stored factors: dst = A_f^{-1} src, with A_f the
     * last factorised matrix (the GMRES preconditioner).
     */
    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src) const;

  private:
    bool
    factorize(const dealii::TrilinosWrappers::SparseMatrix &matrix,
              std::string                                  &message);
    LinearSolveInfo
    krylov_solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                 const dealii::TrilinosWrappers::MPI::Vector  &rhs,
                 const unsigned int                            max_iterations,
                 dealii::TrilinosWrappers::MPI::Vector        &solution);

    const LinearSolverSettings settings;
    /** Own copy of the factorised matrix: Amesos keeps a pointer to it. */
    dealii::TrilinosWrappers::SparseMatrix factored_matrix;
    std::unique_ptr<Epetra_LinearProblem>  problem;
    std::unique_ptr<Amesos_BaseSolver>     direct;
    /** Set instead of @p direct when UMFPACK is chosen. */
    std::unique_ptr<UmfpackFactors> umfpack;
    /** Name of the LU in messages: "Amesos_Klu" or "UMFPACK". */
    std::string     package;
    bool            has_factors = false;
    ReuseStatistics counters;
  };
} // namespace FloorBlock::Solver
