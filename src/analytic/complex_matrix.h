#pragma once

#include <complex>
#include <vector>

namespace FloorBlock::Analytic
{
  /** @brief A small dense square complex matrix, row-major. */
  struct ComplexMatrix
  {
    unsigned int                      n = 0;
    std::vector<std::complex<double>> entries;

    explicit ComplexMatrix(const unsigned int size = 0)
      : n(size)
      , entries(size * size, 0.)
    {}
    std::complex<double> &
    operator()(const unsigned int i, const unsigned int j)
    {
      return entries[i * n + j];
    }
    const std::complex<double> &
    operator()(const unsigned int i, const unsigned int j) const
    {
      return entries[i * n + j];
    }
  };

  /**
   * @brief Gaussian elimination with full pivoting: the determinant, and
   * in @p null_vector (if given) the solution with the last pivot's
   * unknown set to 1, scaled to max |.| = 1 -- the null vector when the
   * matrix is singular.
   */
  std::complex<double>
  eliminate(ComplexMatrix                      matrix,
            std::vector<std::complex<double>> *null_vector = nullptr);

  /**
   * @brief |det M| over the product of M's row norms (Hadamard's bound):
   * 1 for orthogonal rows, ~1e-16 for a singular matrix. Tells a zero of
   * the determinant from rows that merely shrink together.
   */
  double
  hadamard_ratio(const ComplexMatrix &matrix);

  /**
   * @brief A null vector of the rectangular matrix made of the columns
   * @p columns of @p matrix (full-pivot elimination; pivots below
   * @p relative_pivot times the largest entry count as zero), returned
   * at full length with zeros outside @p columns and max |.| = 1; empty
   * when those columns are independent.
   */
  std::vector<std::complex<double>>
  null_vector_in_columns(const ComplexMatrix             &matrix,
                         const std::vector<unsigned int> &columns,
                         double                           relative_pivot);
} // namespace FloorBlock::Analytic
