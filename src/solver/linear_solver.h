#pragma once

#include <solver/near_null_space.h>
#include <solver/solver_kinds.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

namespace FloorBlock::Solver
{
  /** @brief Plain settings of the linear solver (no ParameterHandler). */
  struct LinearSolverSettings
  {
    LinearSolverKind kind = LinearSolverKind::automatic;
    /** Largest system (number of DoFs) that `automatic` solves directly. */
    unsigned int max_direct_dofs = 400000;
    /**
     * Amesos package. "Amesos_Klu" works; "Amesos_Umfpack" throws (with
     * an empty message) in the Debian 12 Trilinos build, so it is not the
     * default.
     */
    std::string direct_package = "Amesos_Klu";
    /** GMRES stop: residual below this fraction of the right-hand side. */
    double relative_tolerance = 1e-10;
    /** GMRES iteration cap. */
    unsigned int max_iterations = 2000;
    /**
     * ReusedFactorization: GMRES iterations tried on the factors of an
     * earlier matrix before the current one is factorised afresh; 0
     * factorises every matrix. One iteration costs a pair of triangular
     * solves, about 1/25 of a numeric factorisation on the default mesh,
     * so 20 keeps a failed attempt below the cost of one factorisation.
     */
    unsigned int max_reuse_iterations = 20;
    /** ReusedFactorization's LU (the stateless solve uses direct_package). */
    DirectSolverKind direct_solver = DirectSolverKind::automatic;
    /**
     * `automatic` factorises systems of at least this many DoFs with
     * UMFPACK: the crossover measured on the floor scenes lies between
     * 5.5k DoFs (KLU 14 ms, UMFPACK 17 ms per factorisation and solve)
     * and 8.3k (30 ms against 28 ms); at 57k UMFPACK is 3 times faster.
     */
    unsigned int min_umfpack_dofs = 8000;
  };

  /** @brief What one linear solve did. */
  struct LinearSolveInfo
  {
    bool         success      = false;
    bool         used_direct  = false;
    unsigned int n_iterations = 0;
    std::string  message;
  };

  /**
   * @brief Whether every locally owned entry is finite: a direct solver
   * on a singular matrix returns inf or NaN instead of failing.
   */
  bool
  has_only_finite_values(const dealii::TrilinosWrappers::MPI::Vector &vector);

  /**
   * @brief Solves \f$A x = b\f$ for a general (non-symmetric, because of
   * friction) sparse matrix.
   *
   * @param[in] settings Which solver to use.
   * @param[in] matrix The system matrix; constrained rows must carry a
   *   non-zero diagonal.
   * @param[in] rhs Right-hand side.
   * @param[in] null_space Near-null space for ML (Fem::rigid_body_modes);
   *   the direct solver ignores it.
   * @param[out] solution The solution; unchanged on failure.
   * @param[in] forcing Relative residual the caller needs (an inexact
   *   Newton forcing term, Contact::forcing_term()); the iterative solver
   *   stops at the larger of it and LinearSolverSettings::
   *   relative_tolerance, the direct solver ignores it.
   * @return Success flag, which solver ran and its iteration count. A
   *   failure never throws and never leaves NaN in @p solution.
   */
  /**
   * @brief Whether @p settings choose the direct solver for @p n_dofs
   * unknowns (always, never, or up to LinearSolverSettings::
   * max_direct_dofs when automatic).
   */
  bool
  uses_direct_solver(const LinearSolverSettings &settings,
                     const std::size_t           n_dofs);

  LinearSolveInfo
  solve_linear_system(const LinearSolverSettings                   &settings,
                      const dealii::TrilinosWrappers::SparseMatrix &matrix,
                      const dealii::TrilinosWrappers::MPI::Vector  &rhs,
                      const NearNullSpace                          &null_space,
                      dealii::TrilinosWrappers::MPI::Vector        &solution,
                      double forcing = 0.);
} // namespace FloorBlock::Solver
