#include <solver/linear_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <cmath>
#include <exception>

namespace FloorBlock::Solver
{
  namespace
  {
    using dealii::TrilinosWrappers::MPI::Vector;
    using dealii::TrilinosWrappers::SparseMatrix;

    /** ML smoother sweeps per level: two is ML's recommendation for elasticity. */
    constexpr unsigned int ml_smoother_sweeps = 2;
    /** Krylov restart length of GMRES. */
    constexpr unsigned int gmres_restart_length = 200;


    LinearSolveInfo
    solve_direct(const LinearSolverSettings &settings,
                 const SparseMatrix         &matrix,
                 const Vector               &rhs,
                 Vector                     &solution)
    {
      LinearSolveInfo info;
      info.used_direct = true;
      dealii::SolverControl control(1, 0.);
      dealii::TrilinosWrappers::SolverDirect::AdditionalData data(
        false, settings.direct_package);
      dealii::TrilinosWrappers::SolverDirect solver(control, data);
      Vector trial(solution);
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

    LinearSolveInfo
    solve_iterative(const LinearSolverSettings           &settings,
                    const SparseMatrix                   &matrix,
                    const Vector                         &rhs,
                    const std::vector<std::vector<bool>> &constant_modes,
                    Vector                               &solution)
    {
      LinearSolveInfo info;
      dealii::TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
      amg_data.elliptic              = true;
      amg_data.higher_order_elements = false;
      amg_data.smoother_sweeps       = ml_smoother_sweeps;
      amg_data.constant_modes        = constant_modes;
      dealii::TrilinosWrappers::PreconditionAMG preconditioner;
      dealii::SolverControl control(settings.max_iterations,
                                    settings.relative_tolerance *
                                      rhs.l2_norm());
      dealii::TrilinosWrappers::SolverGMRES::AdditionalData gmres_data(
        false, gmres_restart_length);
      dealii::TrilinosWrappers::SolverGMRES solver(control, gmres_data);
      Vector trial(solution);
      trial = 0.;
      try
        {
          preconditioner.initialize(matrix, amg_data);
          solver.solve(matrix, trial, rhs, preconditioner);
        }
      catch (const std::exception &error)
        {
          info.message      = error.what();
          info.n_iterations = control.last_step();
          return info;
        }
      info.n_iterations = control.last_step();
      if (!has_only_finite_values(trial))
        {
          info.message = "GMRES returned non-finite values";
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
  solve_linear_system(const LinearSolverSettings           &settings,
                      const SparseMatrix                   &matrix,
                      const Vector                         &rhs,
                      const std::vector<std::vector<bool>> &constant_modes,
                      Vector                               &solution)
  {
    return uses_direct_solver(settings, matrix.m()) ?
             solve_direct(settings, matrix, rhs, solution) :
             solve_iterative(settings, matrix, rhs, constant_modes, solution);
  }
} // namespace FloorBlock::Solver
