#pragma once

#include <vector>

namespace FloorBlock::AnalyticTest
{
  /**
   * @brief Dense square system for the independent equilibrium checks: the
   * tests assemble the force and moment balances of every block in global
   * coordinates and solve them here, without the closed forms.
   */
  class DenseSystem
  {
  public:
    explicit DenseSystem(const unsigned int n_unknowns);

    /** @brief Add @p value to the matrix entry (row, column). */
    void
    add(const unsigned int row, const unsigned int column, const double value);

    /** @brief Add @p value to the right-hand side of @p row. */
    void
    add_rhs(const unsigned int row, const double value);

    /** @brief Gaussian elimination with partial pivoting. */
    std::vector<double>
    solve() const;

  private:
    unsigned int                     size;
    std::vector<std::vector<double>> matrix;
    std::vector<double>              rhs;
  };
} // namespace FloorBlock::AnalyticTest
