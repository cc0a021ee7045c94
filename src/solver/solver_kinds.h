#pragma once

/**
 * The linear-solver choices, with no other dependency, so that the
 * parameters library parses Solver/Linear solver and Solver/Direct solver
 * straight into them (CMake target floorblock_solver_kinds).
 */
namespace FloorBlock::Solver
{
  /** How the linear system of a Newton step is solved. */
  enum class LinearSolverKind
  {
    automatic, ///< direct up to LinearSolverSettings::max_direct_dofs
    direct,    ///< Amesos (KLU or UMFPACK)
    iterative  ///< GMRES preconditioned by ML algebraic multigrid
  };

  /** Which sparse LU the Newton solves of ReusedFactorization use. */
  enum class DirectSolverKind
  {
    automatic, ///< UMFPACK from LinearSolverSettings::min_umfpack_dofs on
    klu,       ///< Amesos KLU (left-looking, no BLAS)
    umfpack    ///< SuiteSparse UMFPACK (multifrontal, BLAS 3)
  };
} // namespace FloorBlock::Solver
