#include <solver/linear_solver.h>
#include <solver/reused_amg.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <cmath>
#include <exception>

namespace FloorBlock::Solver
{
  namespace
  {
    using dealii::TrilinosWrappers::SparseMatrix;
    using dealii::TrilinosWrappers::MPI::Vector;

    LinearSolveInfo
    solve_direct(const LinearSolverSettings &settings,
                 const SparseMatrix         &matrix,
                 const Vector               &rhs,
                 Vector                     &solution)
    {
      LinearSolveInfo info;
      info.used_direct = true;
      dealii::SolverControl                                  control(1, 0.);
      dealii::TrilinosWrappers::SolverDirect::AdditionalData data(
        false, settings.direct_package);
      dealii::TrilinosWrappers::SolverDirect solver(control, data);
      Vector                                 trial(solution);
      try
        {
          solver.solve(matrix, trial, rhs);
        }
      catch (const std::exception &error)
        {
          info.message = settings.direct_package + ": " + error.what();
          return info;
        }
      if (!has_only_finite_values(trial))
        {
          info.message = settings.direct_package +
                         " returned non-finite values (singular matrix)";
          return info;
        }
      solution     = trial;
      info.success = true;
      return info;
    }
  } // namespace

  bool
  has_only_finite_values(const Vector &vector)
  {
    bool finite = true;
    for (const auto value : vector)
      finite = finite && std::isfinite(value);
    // Every process must take the same branch after a solve.
    return dealii::Utilities::MPI::min(finite ? 1 : 0,
                                       vector.get_mpi_communicator()) == 1;
  }

  bool
  uses_direct_solver(const LinearSolverSettings &settings,
                     const std::size_t           n_dofs)
  {
    return settings.kind == LinearSolverKind::direct ||
           (settings.kind == LinearSolverKind::automatic &&
            n_dofs <= settings.max_direct_dofs);
  }

  LinearSolveInfo
  solve_linear_system(const LinearSolverSettings &settings,
                      const SparseMatrix         &matrix,
                      const Vector               &rhs,
                      const NearNullSpace        &null_space,
                      Vector                     &solution,
                      const double                forcing)
  {
    return uses_direct_solver(settings, matrix.m()) ?
             solve_direct(settings, matrix, rhs, solution) :
             ReusedAmg(settings, null_space)
               .solve(matrix, rhs, solution, forcing);
  }
} // namespace FloorBlock::Solver
