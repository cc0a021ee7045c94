#include <solver/system_solver.h>

namespace FloorBlock::Solver
{
  namespace
  {
    /**
     * The numerics on the processes of @p communicator: on several,
     * `automatic` solves iteratively. Amesos KLU, the distributed direct
     * solver, gathers the matrix on one process and factorises it afresh
     * at every Newton iteration (ReusedFactorization keeps UMFPACK factors
     * on one process only): on params/plane_strain_3d.prm (28.9k DoFs, 2
     * processes) 18.0 s of linear solves against 9.6 s for GMRES + ML.
     */
    LinearSolverSettings
    on_processes(LinearSolverSettings settings, const MPI_Comm communicator)
    {
      if (dealii::Utilities::MPI::n_mpi_processes(communicator) > 1 &&
          settings.kind == LinearSolverKind::automatic)
        settings.kind = LinearSolverKind::iterative;
      return settings;
    }
  } // namespace

  SystemSolver::SystemSolver(
    const LinearSolverSettings           &settings,
    const SystemDescription              &system,
    const MPI_Comm                        communicator,
    const std::function<NearNullSpace()> &near_null_space)
    : settings(on_processes(settings, communicator))
  {
    const bool distributed =
      dealii::Utilities::MPI::n_mpi_processes(communicator) > 1;
    // The choice reads the configured settings: on several processes an
    // `automatic` choice of the direct solver keeps nothing, and each
    // system is then solved by solve_linear_system with the settings for
    // several processes (on_processes), GMRES + ML.
    if (system.saddle_point)
      {
        // The exact law's saddle-point matrix: UMFPACK factorised it
        // faster than KLU at every size measured (params/s6.prm, 4.0k
        // unknowns: 0.32 s against 0.70 s for all solves; 1.9k: 0.12
        // against 0.13 s), unlike the compliant law's stiffness matrix,
        // where the crossover lies near 8k DoFs.
        LinearSolverSettings linear = settings;
        linear.min_umfpack_dofs     = 0;
        direct_solver = std::make_unique<ReusedFactorization>(linear);
      }
    else if (!distributed && uses_direct_solver(settings, system.n_dofs))
      direct_solver = std::make_unique<ReusedFactorization>(settings);
    else if (!uses_direct_solver(settings, system.n_dofs))
      amg_solver = std::make_unique<ReusedAmg>(settings, near_null_space());
  }

  LinearSolveInfo
  SystemSolver::solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                      const dealii::TrilinosWrappers::MPI::Vector  &rhs,
                      dealii::TrilinosWrappers::MPI::Vector        &solution,
                      const double                                  forcing)
  {
    // A distributed direct solve (Solver/Linear solver = direct on several
    // processes) keeps nothing between iterations and needs no near-null
    // space.
    if (direct_solver)
      return direct_solver->solve(matrix, rhs, solution);
    if (amg_solver)
      return amg_solver->solve(matrix, rhs, solution, forcing);
    return solve_linear_system(
      settings, matrix, rhs, NearNullSpace(), solution);
  }

  SystemSolverStatistics
  SystemSolver::statistics() const
  {
    SystemSolverStatistics statistics;
    if (amg_solver)
      {
        statistics.iterative    = true;
        statistics.n_amg_setups = amg_solver->statistics().n_setups;
        statistics.n_amg_krylov_iterations =
          amg_solver->statistics().n_krylov_iterations;
      }
    if (direct_solver)
      {
        statistics.direct = true;
        statistics.n_factorizations =
          direct_solver->statistics().n_factorizations;
        statistics.n_krylov_iterations =
          direct_solver->statistics().n_krylov_iterations;
        statistics.n_solves_above_tolerance =
          direct_solver->statistics().n_accepted_above_tolerance;
      }
    return statistics;
  }
} // namespace FloorBlock::Solver
