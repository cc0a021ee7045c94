#pragma once

#include <vector>

namespace FloorBlock::RigidBlocks
{
  /**
   * @brief Square dense matrix, row major. The rigid-block tangent has
   * 3 n rows (n <= 99 blocks), small enough that a dense LU costs less
   * than assembling the joints.
   */
  struct DenseMatrix
  {
    explicit DenseMatrix(const unsigned int size = 0);

    unsigned int        size;
    std::vector<double> values;

    double &
    operator()(const unsigned int row, const unsigned int column);
    double
    operator()(const unsigned int row, const unsigned int column) const;
    /** @brief Set every entry to zero. */
    void
    clear_values();
  };

  /** @brief Outcome of solve_dense(). */
  struct DenseSolveResult
  {
    bool success = false;
    /** Row of the first (near) zero pivot when !success. */
    unsigned int singular_row = 0;
  };

  /**
   * @brief Solve matrix x = rhs by LU with partial pivoting, in place
   * (both arguments are overwritten; rhs becomes x).
   * @param[in] relative_pivot_tolerance A pivot below this times the
   *   largest absolute diagonal entry of the input counts as singular.
   * @return success, or the row where elimination broke down.
   */
  DenseSolveResult
  solve_dense(DenseMatrix         &matrix,
              std::vector<double> &rhs,
              const double         relative_pivot_tolerance);
} // namespace FloorBlock::RigidBlocks
