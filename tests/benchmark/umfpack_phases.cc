#include <solver/umfpack_factors.h>

#include <Epetra_CrsMatrix.h>

#include <stdexcept>
#include <vector>

#include "direct_solver_phases.h"
#include "measurements.h"

namespace FloorBlock::Benchmark
{
  std::map<std::string, double>
  umfpack_phase_times(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                      const dealii::TrilinosWrappers::MPI::Vector  &rhs)
  {
    // The product's own UMFPACK interface (Solver::UmfpackFactors, used by
    // the contact solver above min_umfpack_dofs), phase by phase.
    Solver::UmfpackFactors factors;
    factors.set_matrix(matrix.trilinos_matrix());
    const std::vector<double> right_hand_side(rhs.begin(), rhs.end());
    std::vector<double>       solution(right_hand_side.size());

    std::map<std::string, double> seconds;
    const auto timed = [&](const std::string &phase, const auto &work) {
      const Stopwatch clock;
      work();
      seconds[phase] = clock.cpu_seconds();
    };
    const auto solve = [&]() {
      factors.solve(right_hand_side.data(), solution.data());
    };
    timed("symbolic", [&]() { factors.analyse(); });
    timed("numeric", [&]() { factors.factorize_numeric(); });
    timed("solve", solve);
    timed("numeric again", [&]() { factors.factorize_numeric(); });
    timed("solve again", solve);
    return seconds;
  }
} // namespace FloorBlock::Benchmark
