#include <solver/reused_amg.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

namespace FloorBlock::Solver
{
  namespace
  {
    /** ML smoother sweeps per level: two is ML's recommendation for elasticity. */
    constexpr unsigned int ml_smoother_sweeps = 2;
    /** Krylov restart length of GMRES. */
    constexpr unsigned int gmres_restart_length = 200;
  } // namespace

  ReusedAmg::ReusedAmg(const LinearSolverSettings           &settings,
                       const std::vector<std::vector<bool>> &constant_modes)
    : settings(settings)
    , modes(constant_modes)
  {}

  void
  ReusedAmg::build(const dealii::TrilinosWrappers::SparseMatrix &matrix)
  {
    dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = ml_smoother_sweeps;
    data.constant_modes        = modes;
    // A setup that throws leaves no hierarchy to keep.
    has_hierarchy = false;
    preconditioner.initialize(matrix, data);
    has_hierarchy = true;
    ++counters.n_setups;
  }

  bool
  ReusedAmg::gmres(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                   const dealii::TrilinosWrappers::MPI::Vector  &rhs,
                   const double                 relative_tolerance,
                   const unsigned int           max_iterations,
                   dealii::TrilinosWrappers::MPI::Vector        &trial,
                   LinearSolveInfo                              &info)
  {
    // Silent: hitting the cap on a kept hierarchy is the expected signal
    // to rebuild it.
    dealii::SolverControl control(max_iterations,
                                  relative_tolerance * rhs.l2_norm(),
                                  false,
                                  false);
    dealii::TrilinosWrappers::SolverGMRES::AdditionalData data(
      false, gmres_restart_length);
    dealii::TrilinosWrappers::SolverGMRES solver(control, data);
    trial = 0.;
    bool converged = true;
    try
      {
        solver.solve(matrix, trial, rhs, preconditioner);
      }
    catch (const dealii::SolverControl::NoConvergence &)
      {
        converged = false;
      }
    info.n_iterations += control.last_step();
    counters.n_krylov_iterations += control.last_step();
    return converged;
  }

  LinearSolveInfo
  ReusedAmg::solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                   const dealii::TrilinosWrappers::MPI::Vector  &rhs,
                   dealii::TrilinosWrappers::MPI::Vector        &solution,
                   const double                                  forcing)
  {
    ++counters.n_solves;
    LinearSolveInfo info;
    const double tolerance = std::max(settings.relative_tolerance, forcing);
    const double decades   = std::max(1., -std::log10(tolerance));
    dealii::TrilinosWrappers::MPI::Vector trial(solution);
    try
      {
        bool converged = false;
        if (has_hierarchy)
          {
            const auto allowance = static_cast<unsigned int>(std::ceil(
              reuse_allowance * fresh_iterations_per_decade * decades));
            converged = gmres(matrix,
                              rhs,
                              tolerance,
                              std::min(allowance, settings.max_iterations),
                              trial,
                              info);
          }
        if (!converged)
          {
            build(matrix);
            const unsigned int before = info.n_iterations;
            if (!gmres(matrix,
                       rhs,
                       tolerance,
                       settings.max_iterations,
                       trial,
                       info))
              {
                info.message = "GMRES + ML: no convergence in " +
                               std::to_string(settings.max_iterations) +
                               " iterations";
                return info;
              }
            fresh_iterations_per_decade =
              std::max(1., (info.n_iterations - before) / decades);
          }
      }
    catch (const std::exception &error)
      {
        info.message = error.what();
        return info;
      }
    if (!has_only_finite_values(trial))
      {
        info.message = "GMRES returned non-finite values";
        return info;
      }
    solution     = trial;
    info.success = true;
    return info;
  }

  const AmgStatistics &
  ReusedAmg::statistics() const
  {
    return counters;
  }
} // namespace FloorBlock::Solver
