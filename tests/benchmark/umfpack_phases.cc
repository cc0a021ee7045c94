#include "direct_solver_phases.h"

#include "measurements.h"

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <suitesparse/umfpack.h>

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace FloorBlock::Benchmark
{
  namespace
  {
    /** Compressed rows of a serial Epetra matrix, columns sorted per row. */
    struct CompressedRows
    {
      std::vector<SuiteSparse_long> row_start;
      std::vector<SuiteSparse_long> columns;
      std::vector<double>           values;
    };

    CompressedRows
    compressed_rows(const Epetra_CrsMatrix &matrix)
    {
      CompressedRows rows;
      const int      n_rows = matrix.NumMyRows();
      rows.row_start.push_back(0);
      std::vector<std::pair<SuiteSparse_long, double>> entries;
      for (int row = 0; row < n_rows; ++row)
        {
          int     n_entries = 0;
          double *values    = nullptr;
          int    *indices   = nullptr;
          matrix.ExtractMyRowView(row, n_entries, values, indices);
          entries.clear();
          for (int k = 0; k < n_entries; ++k)
            entries.emplace_back(matrix.GCID64(indices[k]), values[k]);
          std::sort(entries.begin(), entries.end());
          for (const auto &[column, value] : entries)
            {
              rows.columns.push_back(column);
              rows.values.push_back(value);
            }
          rows.row_start.push_back(rows.columns.size());
        }
      return rows;
    }

    void
    check(const SuiteSparse_long status, const char *phase)
    {
      // Warnings (> 0, e.g. a singular matrix) count as failures too: the
      // benchmark's matrix is regular.
      if (status != UMFPACK_OK)
        throw std::runtime_error(std::string("UMFPACK ") + phase +
                                 " failed with status " +
                                 std::to_string(status));
    }
  } // namespace

  std::map<std::string, double>
  umfpack_phase_times(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                      const dealii::TrilinosWrappers::MPI::Vector  &rhs)
  {
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    if (epetra.NumMyRows() != epetra.NumGlobalRows())
      throw std::runtime_error("UMFPACK phases need a serial matrix");
    const CompressedRows rows = compressed_rows(epetra);
    const auto           n    = static_cast<SuiteSparse_long>(epetra.NumMyRows());
    std::vector<double>  right_hand_side(rhs.begin(), rhs.end());
    std::vector<double>  solution(right_hand_side.size());

    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    umfpack_dl_defaults(control);
    void *symbolic = nullptr, *numeric = nullptr;
    std::map<std::string, double> seconds;
    const auto timed = [&](const std::string &phase, const auto &work) {
      const Stopwatch clock;
      check(work(), phase.c_str());
      seconds[phase] = clock.cpu_seconds();
    };
    // The compressed rows of A are the compressed columns of A^T, so
    // solving with UMFPACK_At gives A x = b at the cost of A.
    const SuiteSparse_long *starts  = rows.row_start.data();
    const SuiteSparse_long *columns = rows.columns.data();
    const double           *values  = rows.values.data();
    const auto factor_numeric = [&]() {
      if (numeric != nullptr)
        umfpack_dl_free_numeric(&numeric);
      return umfpack_dl_numeric(
        starts, columns, values, symbolic, &numeric, control, info);
    };
    const auto solve = [&]() {
      return umfpack_dl_solve(UMFPACK_At, starts, columns, values,
                              solution.data(), right_hand_side.data(),
                              numeric, control, info);
    };
    try
      {
        timed("symbolic", [&]() {
          return umfpack_dl_symbolic(
            n, n, starts, columns, values, &symbolic, control, info);
        });
        timed("numeric", factor_numeric);
        timed("solve", solve);
        timed("numeric again", factor_numeric);
        timed("solve again", solve);
      }
    catch (...)
      {
        umfpack_dl_free_numeric(&numeric);
        umfpack_dl_free_symbolic(&symbolic);
        throw;
      }
    umfpack_dl_free_numeric(&numeric);
    umfpack_dl_free_symbolic(&symbolic);
    return seconds;
  }
} // namespace FloorBlock::Benchmark
