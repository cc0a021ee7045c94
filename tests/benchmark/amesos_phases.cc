#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>

#include <memory>
#include <stdexcept>

#include "direct_solver_phases.h"
#include "measurements.h"

namespace FloorBlock::Benchmark
{
  std::map<std::string, double>
  amesos_phase_times(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                     const dealii::TrilinosWrappers::MPI::Vector  &rhs,
                     const std::string                            &package)
  {
    // Amesos takes non-const pointers but does not modify the matrix.
    auto &operator_matrix =
      const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
    Epetra_MultiVector   right_hand_side(rhs.trilinos_vector());
    Epetra_MultiVector   solution(operator_matrix.DomainMap(), 1);
    Epetra_LinearProblem problem(&operator_matrix, &solution, &right_hand_side);
    Amesos               factory;
    std::unique_ptr<Amesos_BaseSolver> solver(
      factory.Create(package.c_str(), problem));
    if (!solver)
      throw std::runtime_error("Amesos has no package " + package);

    std::map<std::string, double> seconds;
    const auto timed = [&](const std::string &phase, const auto &work) {
      const Stopwatch clock;
      if (work() != 0)
        throw std::runtime_error(package + ": " + phase + " failed");
      seconds[phase] = clock.cpu_seconds();
    };
    timed("symbolic", [&]() { return solver->SymbolicFactorization(); });
    timed("numeric", [&]() { return solver->NumericFactorization(); });
    timed("solve", [&]() { return solver->Solve(); });
    timed("numeric again", [&]() { return solver->NumericFactorization(); });
    timed("solve again", [&]() { return solver->Solve(); });
    return seconds;
  }
} // namespace FloorBlock::Benchmark
