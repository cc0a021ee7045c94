// ReusedAmg: GMRES + ML meets the residual asked for (the forcing term or
// the solver's own tolerance, whichever is larger), keeps its hierarchy for
// a small change of the matrix and rebuilds it for a large one.
#include <solver/reused_amg.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <gtest/gtest.h>
#include <mpi.h>

#include "tridiagonal_pattern.h"

namespace
{
  using namespace FloorBlock;
  using dealii::TrilinosWrappers::SparseMatrix;
  using dealii::TrilinosWrappers::MPI::Vector;
  using FloorBlockTest::relative_residual;

  constexpr unsigned int n = 400;

  /**
   * A 1D Laplacian with Dirichlet ends (2 on the diagonal, -1 beside it:
   * condition number about 4 n^2 / pi^2 = 6.5e4, where plain GMRES would
   * need hundreds of iterations) plus @p shift on the diagonal of rows
   * [first, last).
   */
  void
  fill(SparseMatrix      &matrix,
       const unsigned int first,
       const unsigned int last,
       const double       shift)
  {
    matrix = 0.;
    for (unsigned int i = 0; i < n; ++i)
      {
        matrix.set(i, i, 2. + (i >= first && i < last ? shift : 0.));
        if (i > 0)
          matrix.set(i, i - 1, -1.);
        if (i + 1 < n)
          matrix.set(i, i + 1, -1.);
      }
    matrix.compress(dealii::VectorOperation::insert);
  }

  class ReusedAmgTest : public ::testing::Test
  {
  protected:
    FloorBlockTest::TridiagonalSystem system{n};
    SparseMatrix                     &matrix = system.matrix;
    Vector                           &rhs    = system.rhs;
    Vector                           &x      = system.x;
    Solver::LinearSolverSettings      settings;
    /** One component: the constant is the near-null space. */
    const Solver::NearNullSpace modes{1, {std::vector<double>(n, 1.)}};
  };

  TEST_F(ReusedAmgTest, MeetsTheForcingTermAndNotMore)
  {
    Solver::ReusedAmg solver(settings, modes);
    fill(matrix, 0, 0, 0.);
    const Solver::LinearSolveInfo loose = solver.solve(matrix, rhs, x, 1e-2);
    ASSERT_TRUE(loose.success) << loose.message;
    EXPECT_LE(relative_residual(matrix, x, rhs), 1e-2);

    const Solver::LinearSolveInfo tight = solver.solve(matrix, rhs, x, 0.);
    ASSERT_TRUE(tight.success) << tight.message;
    EXPECT_LE(relative_residual(matrix, x, rhs), settings.relative_tolerance);
    // The loose solve stopped at the forcing term, not at 1e-10.
    EXPECT_GT(tight.n_iterations, loose.n_iterations);
  }

  TEST_F(ReusedAmgTest, SmallChangeKeepsTheHierarchy)
  {
    Solver::ReusedAmg solver(settings, modes);
    fill(matrix, 0, 0, 0.);
    ASSERT_TRUE(solver.solve(matrix, rhs, x, 0.).success);
    EXPECT_EQ(solver.statistics().n_setups, 1u);

    // Three rows stiffened a little, as a few joint pairs closing do.
    fill(matrix, 200, 203, 0.1);
    ASSERT_TRUE(solver.solve(matrix, rhs, x, 0.).success);
    EXPECT_LE(relative_residual(matrix, x, rhs), settings.relative_tolerance);
    EXPECT_EQ(solver.statistics().n_setups, 1u);
    EXPECT_EQ(solver.statistics().n_solves, 2u);
  }

  TEST_F(ReusedAmgTest, LargeChangeRebuildsTheHierarchy)
  {
    Solver::ReusedAmg solver(settings, modes);
    fill(matrix, 0, 0, 0.);
    ASSERT_TRUE(solver.solve(matrix, rhs, x, 0.).success);

    // Half the rows a thousand times stiffer: the Laplacian's hierarchy
    // no longer fits, and the solve must still meet the tolerance.
    fill(matrix, 0, n / 2, 2e3);
    const Solver::LinearSolveInfo info = solver.solve(matrix, rhs, x, 0.);
    ASSERT_TRUE(info.success) << info.message;
    EXPECT_LE(relative_residual(matrix, x, rhs), settings.relative_tolerance);
    EXPECT_EQ(solver.statistics().n_setups, 2u);
  }

  TEST_F(ReusedAmgTest, NoConvergenceFailsWithoutTouchingTheSolution)
  {
    // A residual below round-off cannot be reached in three iterations.
    settings.relative_tolerance = 1e-20;
    settings.max_iterations     = 3;
    Solver::ReusedAmg solver(settings, modes);
    fill(matrix, 0, 0, 0.);
    x = 7.;
    Solver::LinearSolveInfo info;
    ASSERT_NO_THROW(info = solver.solve(matrix, rhs, x, 0.));
    EXPECT_FALSE(info.success);
    EXPECT_FALSE(info.message.empty());
    EXPECT_EQ(x(0), 7.);
    EXPECT_EQ(x(n - 1), 7.);
  }
} // namespace
