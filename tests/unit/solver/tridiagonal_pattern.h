#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

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
      for (unsigned int j = (i > 0 ? i - 1 : 0); j <= std::min(i + 1, n - 1); ++j)
        pattern.add(i, j);
    pattern.compress();
  }
} // namespace FloorBlockTest
