#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <mpi.h>

#include <algorithm>

namespace FloorBlockTest
{
  /** @brief The compressed pattern of an n x n tridiagonal matrix, one process. */
  inline void
  make_tridiagonal_pattern(const unsigned int                         n,
                           dealii::TrilinosWrappers::SparsityPattern &pattern)
  {
    const dealii::IndexSet all = dealii::complete_index_set(n);
    pattern.reinit(all, all, MPI_COMM_SELF);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j <= std::min(i + 1, n - 1);
           ++j)
        pattern.add(i, j);
    pattern.compress();
  }

  /**
   * @brief An n x n system on one process with a tridiagonal pattern: the
   * matrix (to be filled by the test), rhs_i = 1 + 0.01 i and x = 0.
   */
  struct TridiagonalSystem
  {
    explicit TridiagonalSystem(const unsigned int n)
    {
      const dealii::IndexSet all = dealii::complete_index_set(n);
      make_tridiagonal_pattern(n, pattern);
      matrix.reinit(pattern);
      rhs.reinit(all, MPI_COMM_SELF);
      x.reinit(all, MPI_COMM_SELF);
      for (unsigned int i = 0; i < n; ++i)
        rhs(i) = 1. + 0.01 * i;
      rhs.compress(dealii::VectorOperation::insert);
    }

    dealii::TrilinosWrappers::SparsityPattern pattern;
    dealii::TrilinosWrappers::SparseMatrix    matrix;
    dealii::TrilinosWrappers::MPI::Vector     rhs, x;
  };

  /** @brief |b - A x| / |b|. */
  inline double
  relative_residual(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                    const dealii::TrilinosWrappers::MPI::Vector  &x,
                    const dealii::TrilinosWrappers::MPI::Vector  &b)
  {
    dealii::TrilinosWrappers::MPI::Vector r(b);
    matrix.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }
} // namespace FloorBlockTest
