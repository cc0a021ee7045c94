#include "dense_solver.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace FloorBlock::AnalyticTest
{
  DenseSystem::DenseSystem(const unsigned int n_unknowns)
    : size(n_unknowns)
    , matrix(n_unknowns, std::vector<double>(n_unknowns, 0.))
    , rhs(n_unknowns, 0.)
  {}

  void
  DenseSystem::add(const unsigned int row,
                   const unsigned int column,
                   const double       value)
  {
    matrix.at(row).at(column) += value;
  }

  void
  DenseSystem::add_rhs(const unsigned int row, const double value)
  {
    rhs.at(row) += value;
  }

  std::vector<double>
  DenseSystem::solve() const
  {
    std::vector<std::vector<double>> work     = matrix;
    std::vector<double>              solution = rhs;
    for (unsigned int pivot = 0; pivot < size; ++pivot)
      {
        unsigned int best = pivot;
        for (unsigned int row = pivot + 1; row < size; ++row)
          if (std::abs(work[row][pivot]) > std::abs(work[best][pivot]))
            best = row;
        if (work[best][pivot] == 0.)
          throw std::runtime_error("singular equilibrium system");
        std::swap(work[pivot], work[best]);
        std::swap(solution[pivot], solution[best]);
        for (unsigned int row = pivot + 1; row < size; ++row)
          {
            const double factor = work[row][pivot] / work[pivot][pivot];
            for (unsigned int column = pivot; column < size; ++column)
              work[row][column] -= factor * work[pivot][column];
            solution[row] -= factor * solution[pivot];
          }
      }
    for (unsigned int row = size; row-- > 0;)
      {
        for (unsigned int column = row + 1; column < size; ++column)
          solution[row] -= work[row][column] * solution[column];
        solution[row] /= work[row][row];
      }
    return solution;
  }
} // namespace FloorBlock::AnalyticTest
