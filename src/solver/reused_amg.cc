#include <solver/reused_amg.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>

namespace FloorBlock::Solver
{
  namespace
  {
    /** ML smoother sweeps per level: two is ML's recommendation for elasticity.
     */
    constexpr unsigned int ml_smoother_sweeps = 2;
    /**
     * W-cycles: each coarse level is visited twice per cycle. With a
     * V-cycle the GMRES iterations per solve grew with the levels of the
     * hierarchy (3D plane-strain scene, first twelve solves to 1e-8:
     * 45-129 on 10.5k DoFs, 49-141 on 471k); with the W-cycle and the
     * rotations in the near-null space 31-105 on 471k. The coarse levels
     * hold a twentieth of the unknowns each, so the second visit is
     * cheap.
     */
    constexpr bool ml_w_cycle = true;
    /** Krylov restart length of GMRES. */
    constexpr unsigned int gmres_restart_length = 200;

    /** The modes as ML reads them: a multivector over the matrix's rows. */
    std::unique_ptr<Epetra_MultiVector>
    null_space_for_ml(const NearNullSpace &null_space, const Epetra_Map &rows)
    {
      const int n_modes = static_cast<int>(null_space.modes.size());
      auto      vectors = std::make_unique<Epetra_MultiVector>(rows, n_modes);
      for (int k = 0; k < n_modes; ++k)
        {
          const std::vector<double> &mode = null_space.modes[k];
          if (mode.size() != static_cast<std::size_t>(rows.NumMyElements()))
            throw std::logic_error("ReusedAmg: a near-null-space mode does "
                                   "not cover the matrix's owned rows");
          std::copy(mode.begin(), mode.end(), (*vectors)[k]);
        }
      return vectors;
    }
  } // namespace

  ReusedAmg::ReusedAmg(const LinearSolverSettings &settings,
                       const NearNullSpace        &null_space)
    : settings(settings)
    , null_space(null_space)
  {}

  void
  ReusedAmg::build(const dealii::TrilinosWrappers::SparseMatrix &matrix)
  {
    dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = ml_smoother_sweeps;
    data.w_cycle               = ml_w_cycle;
    // deal.II's defaults (smoothed aggregation, Chebyshev, KLU on the
    // coarsest level) with no constant modes; ours follow.
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> no_modes;
    data.set_parameters(parameters, no_modes, matrix.trilinos_matrix());
    // No modes given: ML's own, a constant per unknown of a node.
    if (!null_space.modes.empty())
      {
        if (!ml_null_space)
          ml_null_space =
            null_space_for_ml(null_space, matrix.trilinos_matrix().DomainMap());
        parameters.set("PDE equations",
                       static_cast<int>(null_space.n_components));
        parameters.set("null space: type", "pre-computed");
        parameters.set("null space: dimension", ml_null_space->NumVectors());
        parameters.set("null space: vectors", ml_null_space->Values());
      }
    // A setup that throws leaves no hierarchy to keep.
    has_hierarchy = false;
    preconditioner.initialize(matrix, parameters);
    has_hierarchy = true;
    ++counters.n_setups;
  }

  bool
  ReusedAmg::gmres(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                   const dealii::TrilinosWrappers::MPI::Vector  &rhs,
                   const double                           relative_tolerance,
                   const unsigned int                     max_iterations,
                   dealii::TrilinosWrappers::MPI::Vector &trial,
                   LinearSolveInfo                       &info)
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
    trial          = 0.;
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
    const double    tolerance = std::max(settings.relative_tolerance, forcing);
    const double    decades   = std::max(1., -std::log10(tolerance));
    dealii::TrilinosWrappers::MPI::Vector trial(solution);
    try
      {
        bool converged = false;
        if (has_hierarchy)
          {
            const auto allowance = static_cast<unsigned int>(std::ceil(
              reuse_allowance * fresh_iterations_per_decade * decades));
            converged            = gmres(matrix,
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
            if (!gmres(
                  matrix, rhs, tolerance, settings.max_iterations, trial, info))
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
