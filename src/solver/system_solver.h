#pragma once

#include <solver/linear_solver.h>
#include <solver/near_null_space.h>
#include <solver/reused_amg.h>
#include <solver/reused_factorization.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cstddef>
#include <functional>
#include <memory>

namespace FloorBlock::Solver
{
  /** @brief What the linear systems of a nonlinear solve look like. */
  struct SystemDescription
  {
    /** Unknowns of the displacement system (DoFs). */
    std::size_t n_dofs = 0;
    /**
     * The systems are saddle points (displacements and Lagrange
     * multipliers): direct solver only, on one process.
     */
    bool saddle_point = false;
  };

  /** @brief Counters of the kept solver of a SystemSolver. */
  struct SystemSolverStatistics
  {
    /** Whether ReusedAmg solves (the amg_* counters are set). */
    bool         iterative               = false;
    unsigned int n_amg_setups            = 0;
    unsigned int n_amg_krylov_iterations = 0;
    /** Whether ReusedFactorization solves (the counters below are set). */
    bool         direct                   = false;
    unsigned int n_factorizations         = 0;
    unsigned int n_krylov_iterations      = 0;
    unsigned int n_solves_above_tolerance = 0;
  };

  /**
   * @brief The linear solver of a sequence of Newton systems, chosen once
   * from the settings, the system size and the number of processes, and
   * kept (with its LU factors or AMG hierarchy) for the whole sequence.
   *
   * The choice, made with the configured settings: a saddle-point system
   * is factorised by UMFPACK; a displacement system up to
   * LinearSolverSettings::max_direct_dofs (or with `direct`) is
   * factorised and the factors are reused on one process
   * (ReusedFactorization); on several processes such a system keeps
   * nothing: each is solved by solve_linear_system, where `automatic`
   * means GMRES + ML; above the limit, or with `iterative`, GMRES + ML
   * with the near-null space and a kept hierarchy (ReusedAmg).
   */
  class SystemSolver
  {
  public:
    /**
     * @param[in] settings Configured numerics.
     * @param[in] system Size and kind of the systems.
     * @param[in] communicator Processes that share the systems.
     * @param[in] near_null_space Called once if the iterative solver is
     *   chosen (Fem::rigid_body_modes).
     */
    SystemSolver(const LinearSolverSettings           &settings,
                 const SystemDescription              &system,
                 const MPI_Comm                        communicator,
                 const std::function<NearNullSpace()> &near_null_space);

    /**
     * @brief Solves matrix x = rhs.
     * @param[in] forcing Relative residual the caller needs (inexact
     *   Newton); only the iterative solver uses it.
     * @param[in,out] solution Result; unchanged on failure.
     */
    LinearSolveInfo
    solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
          const dealii::TrilinosWrappers::MPI::Vector  &rhs,
          dealii::TrilinosWrappers::MPI::Vector        &solution,
          const double                                  forcing);

    SystemSolverStatistics
    statistics() const;

  private:
    /**
     * The settings with `automatic` resolved for several processes: those
     * of the solves that keep nothing (solve_linear_system).
     */
    const LinearSolverSettings settings;
    /** Set when the systems are factorised and the factors kept. */
    std::unique_ptr<ReusedFactorization> direct_solver;
    /** Set instead when GMRES + ML solves (large or distributed systems). */
    std::unique_ptr<ReusedAmg> amg_solver;
  };
} // namespace FloorBlock::Solver
