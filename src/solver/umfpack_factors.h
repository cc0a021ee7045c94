#pragma once

#include <suitesparse/SuiteSparse_config.h>

#include <string>
#include <vector>

class Epetra_CrsMatrix;

namespace FloorBlock::Solver
{
  /**
   * @brief LU factors of a serial sparse matrix by SuiteSparse UMFPACK,
   * called directly: Amesos_Umfpack throws in Debian 12's Trilinos, and
   * deal.II's SparseDirectUMFPACK does not take Trilinos matrices.
   *
   * UMFPACK is multifrontal and uses BLAS 3, so with OpenBLAS its numeric
   * factorisation grows as DoFs^1.3 against KLU's DoFs^1.9 on the floor
   * scenes (3 times faster at 57k DoFs, slower below about 10k;
   * results/FINDINGS.md, section 11). The symbolic analysis is kept while the
   * pattern stays the same.
   */
  class UmfpackFactors
  {
  public:
    UmfpackFactors();
    ~UmfpackFactors();
    UmfpackFactors(const UmfpackFactors &) = delete;
    UmfpackFactors &
    operator=(const UmfpackFactors &) = delete;

    /**
     * @brief Copies the values of @p matrix (all rows on this process,
     * numbered 0 .. n-1); drops the numeric factors, and with a new
     * pattern the symbolic analysis too.
     */
    void
    set_matrix(const Epetra_CrsMatrix &matrix);

    /** @brief Symbolic analysis of the pattern; throws std::runtime_error. */
    void
    analyse();

    /**
     * @brief Numeric factorisation of the last set_matrix() (analyses
     * first if needed); throws std::runtime_error naming the UMFPACK
     * status, also for a singular matrix.
     */
    void
    factorize_numeric();

    /** @brief set_matrix() and factorize_numeric(). */
    void
    factorize(const Epetra_CrsMatrix &matrix);

    /**
     * @brief x = A^-1 b with the factors, without UMFPACK's own iterative
     * refinement (callers that need a residual check do their own).
     */
    void
    solve(const double *rhs, double *solution) const;

    bool
    has_factors() const;

  private:
    /** Compressed rows of A, read by UMFPACK as the columns of A^T. */
    std::vector<SuiteSparse_long> row_start;
    std::vector<SuiteSparse_long> columns;
    std::vector<double>           values;
    std::vector<double>           control;
    void                         *symbolic = nullptr;
    void                         *numeric  = nullptr;
  };
} // namespace FloorBlock::Solver
