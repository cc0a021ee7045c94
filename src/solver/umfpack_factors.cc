#include <solver/umfpack_factors.h>

#include <Epetra_CrsMatrix.h>
#include <suitesparse/umfpack.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace FloorBlock::Solver
{
  namespace
  {
    void
    check(const SuiteSparse_long status, const char *phase)
    {
      // Warnings (> 0) include a singular matrix: a failure here.
      if (status != UMFPACK_OK)
        throw std::runtime_error(
          std::string("UMFPACK ") + phase + " failed with status " +
          std::to_string(status) +
          (status == UMFPACK_WARNING_singular_matrix ? " (singular matrix)" :
                                                       ""));
    }
  } // namespace

  UmfpackFactors::UmfpackFactors()
    : control(UMFPACK_CONTROL)
  {
    umfpack_dl_defaults(control.data());
    control[UMFPACK_IRSTEP] = 0;
  }

  UmfpackFactors::~UmfpackFactors()
  {
    if (numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
    if (symbolic != nullptr)
      umfpack_dl_free_symbolic(&symbolic);
  }

  void
  UmfpackFactors::set_matrix(const Epetra_CrsMatrix &matrix)
  {
    // Rows are taken in local order and columns by global index: the
    // two agree only for a serial matrix numbered 0 .. n-1.
    if (matrix.NumMyRows() != matrix.NumGlobalRows() ||
        !matrix.RowMap().LinearMap() || matrix.RowMap().MinMyGID64() != 0)
      throw std::runtime_error("UMFPACK needs every row of the matrix on "
                               "one process, numbered 0 .. n-1");
    std::vector<SuiteSparse_long> new_row_start{0};
    std::vector<SuiteSparse_long> new_columns;
    std::vector<double>           new_values;
    new_columns.reserve(matrix.NumMyNonzeros());
    new_values.reserve(matrix.NumMyNonzeros());
    std::vector<std::pair<SuiteSparse_long, double>> entries;
    for (int row = 0; row < matrix.NumMyRows(); ++row)
      {
        int     n_entries  = 0;
        double *row_values = nullptr;
        int    *indices    = nullptr;
        matrix.ExtractMyRowView(row, n_entries, row_values, indices);
        entries.clear();
        for (int k = 0; k < n_entries; ++k)
          entries.emplace_back(matrix.GCID64(indices[k]), row_values[k]);
        std::sort(entries.begin(), entries.end());
        for (const auto &[column, value] : entries)
          {
            new_columns.push_back(column);
            new_values.push_back(value);
          }
        new_row_start.push_back(new_columns.size());
      }
    // Factors of the old values must not outlive them.
    if (numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
    if (new_row_start != row_start || new_columns != columns)
      {
        if (symbolic != nullptr)
          umfpack_dl_free_symbolic(&symbolic);
        row_start = std::move(new_row_start);
        columns   = std::move(new_columns);
      }
    values = std::move(new_values);
  }

  void
  UmfpackFactors::analyse()
  {
    if (symbolic != nullptr)
      umfpack_dl_free_symbolic(&symbolic);
    const auto n = static_cast<SuiteSparse_long>(row_start.size()) - 1;
    check(umfpack_dl_symbolic(n,
                              n,
                              row_start.data(),
                              columns.data(),
                              values.data(),
                              &symbolic,
                              control.data(),
                              nullptr),
          "symbolic analysis");
  }

  void
  UmfpackFactors::factorize_numeric()
  {
    if (symbolic == nullptr)
      analyse();
    if (numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
    const SuiteSparse_long status = umfpack_dl_numeric(row_start.data(),
                                                       columns.data(),
                                                       values.data(),
                                                       symbolic,
                                                       &numeric,
                                                       control.data(),
                                                       nullptr);
    if (status != UMFPACK_OK && numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
    check(status, "numeric factorisation");
  }

  void
  UmfpackFactors::factorize(const Epetra_CrsMatrix &matrix)
  {
    set_matrix(matrix);
    factorize_numeric();
  }

  void
  UmfpackFactors::solve(const double *rhs, double *solution) const
  {
    if (numeric == nullptr)
      throw std::runtime_error("UMFPACK solve without factors");
    // The compressed rows of A are the compressed columns of A^T:
    // solving the transposed system with them gives A x = b.
    check(umfpack_dl_solve(UMFPACK_At,
                           row_start.data(),
                           columns.data(),
                           values.data(),
                           solution,
                           rhs,
                           numeric,
                           control.data(),
                           nullptr),
          "solve");
  }

  bool
  UmfpackFactors::has_factors() const
  {
    return numeric != nullptr;
  }
} // namespace FloorBlock::Solver
