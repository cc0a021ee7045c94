#include <rigid/dense_system.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace FloorBlock::RigidBlocks
{
  DenseMatrix::DenseMatrix(const unsigned int size)
    : size(size)
    , values(static_cast<std::size_t>(size) * size, 0.)
  {}

  double &
  DenseMatrix::operator()(const unsigned int row, const unsigned int column)
  {
    return values[static_cast<std::size_t>(row) * size + column];
  }

  double
  DenseMatrix::operator()(const unsigned int row,
                          const unsigned int column) const
  {
    return values[static_cast<std::size_t>(row) * size + column];
  }

  void
  DenseMatrix::clear_values()
  {
    std::fill(values.begin(), values.end(), 0.);
  }

  DenseSolveResult
  solve_dense(DenseMatrix         &matrix,
              std::vector<double> &rhs,
              const double         relative_pivot_tolerance)
  {
    const unsigned int size             = matrix.size;
    double             largest_diagonal = 0.;
    for (unsigned int row = 0; row < size; ++row)
      largest_diagonal = std::max(largest_diagonal, std::abs(matrix(row, row)));
    const double pivot_floor = relative_pivot_tolerance * largest_diagonal;

    DenseSolveResult result;
    for (unsigned int column = 0; column < size; ++column)
      {
        unsigned int pivot_row = column;
        for (unsigned int row = column + 1; row < size; ++row)
          if (std::abs(matrix(row, column)) >
              std::abs(matrix(pivot_row, column)))
            pivot_row = row;
        if (!(std::abs(matrix(pivot_row, column)) > pivot_floor))
          {
            result.singular_row = column;
            return result;
          }
        if (pivot_row != column)
          {
            for (unsigned int k = 0; k < size; ++k)
              std::swap(matrix(column, k), matrix(pivot_row, k));
            std::swap(rhs[column], rhs[pivot_row]);
          }
        const double pivot = matrix(column, column);
        for (unsigned int row = column + 1; row < size; ++row)
          {
            const double factor = matrix(row, column) / pivot;
            if (factor == 0.)
              continue;
            for (unsigned int k = column; k < size; ++k)
              matrix(row, k) -= factor * matrix(column, k);
            rhs[row] -= factor * rhs[column];
          }
      }
    for (unsigned int row = size; row-- > 0;)
      {
        double sum = rhs[row];
        for (unsigned int k = row + 1; k < size; ++k)
          sum -= matrix(row, k) * rhs[k];
        rhs[row] = sum / matrix(row, row);
      }
    result.success = true;
    return result;
  }
} // namespace FloorBlock::RigidBlocks
