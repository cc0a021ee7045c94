#include <analytic/complex_matrix.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace FloorBlock::Analytic
{
  using Complex = std::complex<double>;

  Complex
  eliminate(ComplexMatrix matrix, std::vector<Complex> *null_vector)
  {
    const unsigned int        n = matrix.n;
    std::vector<unsigned int> column(n);
    for (unsigned int j = 0; j < n; ++j)
      column[j] = j;
    Complex determinant = 1.;
    for (unsigned int k = 0; k < n; ++k)
      {
        unsigned int pivot_row = k, pivot_column = k;
        double       largest = -1.;
        for (unsigned int i = k; i < n; ++i)
          for (unsigned int j = k; j < n; ++j)
            if (std::abs(matrix(i, j)) > largest)
              {
                largest      = std::abs(matrix(i, j));
                pivot_row    = i;
                pivot_column = j;
              }
        if (pivot_row != k)
          {
            for (unsigned int j = 0; j < n; ++j)
              std::swap(matrix(k, j), matrix(pivot_row, j));
            determinant = -determinant;
          }
        if (pivot_column != k)
          {
            for (unsigned int i = 0; i < n; ++i)
              std::swap(matrix(i, k), matrix(i, pivot_column));
            std::swap(column[k], column[pivot_column]);
            determinant = -determinant;
          }
        determinant *= matrix(k, k);
        if (k + 1 == n || std::abs(matrix(k, k)) == 0.)
          continue;
        for (unsigned int i = k + 1; i < n; ++i)
          {
            const Complex factor = matrix(i, k) / matrix(k, k);
            for (unsigned int j = k; j < n; ++j)
              matrix(i, j) -= factor * matrix(k, j);
          }
      }
    if (null_vector)
      {
        std::vector<Complex> permuted(n, 0.);
        permuted[n - 1] = 1.;
        for (int k = int(n) - 2; k >= 0; --k)
          {
            Complex sum = 0.;
            for (unsigned int j = k + 1; j < n; ++j)
              sum += matrix(k, j) * permuted[j];
            permuted[k] =
              std::abs(matrix(k, k)) > 0. ? -sum / matrix(k, k) : Complex(0.);
          }
        null_vector->assign(n, 0.);
        for (unsigned int k = 0; k < n; ++k)
          (*null_vector)[column[k]] = permuted[k];
        double largest = 0.;
        for (const Complex &value : *null_vector)
          largest = std::max(largest, std::abs(value));
        for (Complex &value : *null_vector)
          value /= largest;
      }
    return determinant;
  }


  double
  hadamard_ratio(const ComplexMatrix &matrix)
  {
    double bound = 1.;
    for (unsigned int i = 0; i < matrix.n; ++i)
      {
        double norm = 0.;
        for (unsigned int j = 0; j < matrix.n; ++j)
          norm += std::norm(matrix(i, j));
        bound *= std::sqrt(norm);
      }
    return bound > 0. ? std::abs(eliminate(matrix)) / bound : 0.;
  }


  std::vector<Complex>
  null_vector_in_columns(const ComplexMatrix             &full,
                         const std::vector<unsigned int> &kept_columns,
                         const double                     relative_pivot)
  {
    const unsigned int                n_rows    = full.n;
    const unsigned int                n_columns = kept_columns.size();
    std::vector<std::vector<Complex>> a(n_rows,
                                        std::vector<Complex>(n_columns));
    double                            largest_entry = 0.;
    for (unsigned int i = 0; i < n_rows; ++i)
      for (unsigned int j = 0; j < n_columns; ++j)
        {
          a[i][j]       = full(i, kept_columns[j]);
          largest_entry = std::max(largest_entry, std::abs(a[i][j]));
        }
    std::vector<unsigned int> column(n_columns);
    for (unsigned int j = 0; j < n_columns; ++j)
      column[j] = j;
    unsigned int rank = 0;
    for (; rank < n_columns && rank < n_rows; ++rank)
      {
        unsigned int pivot_row = rank, pivot_column = rank;
        double       largest = -1.;
        for (unsigned int i = rank; i < n_rows; ++i)
          for (unsigned int j = rank; j < n_columns; ++j)
            if (std::abs(a[i][j]) > largest)
              {
                largest      = std::abs(a[i][j]);
                pivot_row    = i;
                pivot_column = j;
              }
        if (largest <= relative_pivot * largest_entry)
          break;
        std::swap(a[rank], a[pivot_row]);
        for (unsigned int i = 0; i < n_rows; ++i)
          std::swap(a[i][rank], a[i][pivot_column]);
        std::swap(column[rank], column[pivot_column]);
        for (unsigned int i = rank + 1; i < n_rows; ++i)
          {
            const Complex factor = a[i][rank] / a[rank][rank];
            for (unsigned int j = rank; j < n_columns; ++j)
              a[i][j] -= factor * a[rank][j];
          }
      }
    if (rank == n_columns)
      return {};
    // The first free unknown 1, the others 0; back substitution.
    std::vector<Complex> permuted(n_columns, 0.);
    permuted[rank] = 1.;
    for (int k = int(rank) - 1; k >= 0; --k)
      {
        Complex sum = 0.;
        for (unsigned int j = k + 1; j < n_columns; ++j)
          sum += a[k][j] * permuted[j];
        permuted[k] = -sum / a[k][k];
      }
    std::vector<Complex> vector(full.n, 0.);
    double               size = 0.;
    for (unsigned int k = 0; k < n_columns; ++k)
      {
        vector[kept_columns[column[k]]] = permuted[k];
        size                            = std::max(size, std::abs(permuted[k]));
      }
    for (Complex &value : vector)
      value /= size;
    return vector;
  }
} // namespace FloorBlock::Analytic
