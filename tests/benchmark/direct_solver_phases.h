#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <map>
#include <string>

namespace FloorBlock::Benchmark
{
  /**
   * @brief Process CPU time (s) of each phase of one Amesos direct solve of
   * @p matrix x = @p rhs with @p package (the contact solver's default is
   * Amesos_Klu); CPU time, because on a shared machine the wall time of a
   * few milliseconds is mostly waiting. Phases: "symbolic", "numeric",
   * "solve" as deal.II's SolverDirect runs them on every call, then
   * "numeric again" (a refactorisation that keeps the symbolic analysis:
   * the cost per Newton iteration if the solver reused it) and "solve
   * again" (triangular solves only: the cost if the matrix did not change,
   * e.g. between augmented-Lagrangian updates with an unchanged contact
   * state).
   */
  std::map<std::string, double>
  amesos_phase_times(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                     const dealii::TrilinosWrappers::MPI::Vector  &rhs,
                     const std::string                            &package);

  /**
   * @brief The same phases with SuiteSparse UMFPACK called directly (the
   * Amesos_Umfpack wrapper fails in the Debian 12 Trilinos build, see
   * src/solver/linear_solver.h): a multifrontal LU whose dense frontal
   * matrices go through BLAS, unlike KLU, which never calls BLAS. Measures
   * what a different direct solver would cost on the contact solver's
   * matrix. Serial matrices only (one rank).
   */
  std::map<std::string, double>
  umfpack_phase_times(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                      const dealii::TrilinosWrappers::MPI::Vector  &rhs);
} // namespace FloorBlock::Benchmark
