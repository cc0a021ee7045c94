// The stateless linear solve: which solver `automatic` picks, the direct
// and the iterative solve against a manufactured solution, and a singular
// matrix that fails without throwing or leaving NaN.
#include <solver/linear_solver.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <limits>

#include "tridiagonal_pattern.h"

namespace
{
  using namespace FloorBlock;
  using dealii::TrilinosWrappers::SparseMatrix;
  using dealii::TrilinosWrappers::MPI::Vector;
  using Solver::LinearSolverKind;

  constexpr unsigned int n = 100;

  TEST(LinearSolver, AutomaticIsDirectUpToTheDofLimit)
  {
    Solver::LinearSolverSettings settings;
    settings.max_direct_dofs = 60000;
    EXPECT_TRUE(Solver::uses_direct_solver(settings, 60000));
    EXPECT_FALSE(Solver::uses_direct_solver(settings, 60001));
    settings.kind = LinearSolverKind::direct;
    EXPECT_TRUE(Solver::uses_direct_solver(settings, 10000000));
    settings.kind = LinearSolverKind::iterative;
    EXPECT_FALSE(Solver::uses_direct_solver(settings, 10));
  }

  /**
   * Non-symmetric tridiagonal system (4 on the diagonal, -1 and -1.2 off
   * it) with the manufactured solution x_i = sin(i / 10) and b = A x.
   * Diagonal dominance by 1.8 in rows and columns bounds ||A^-1||_2 by
   * 1/1.8, and ||A||_2 <= 6.2: the condition number is below 3.5.
   */
  class LinearSolverTest : public ::testing::Test
  {
  protected:
    void
    SetUp() override
    {
      const dealii::IndexSet all = dealii::complete_index_set(n);
      FloorBlockTest::make_tridiagonal_pattern(n, pattern);
      matrix.reinit(pattern);
      for (unsigned int i = 0; i < n; ++i)
        {
          matrix.set(i, i, 4.);
          if (i > 0)
            matrix.set(i, i - 1, -1.);
          if (i + 1 < n)
            matrix.set(i, i + 1, -1.2);
        }
      matrix.compress(dealii::VectorOperation::insert);
      exact.reinit(all, MPI_COMM_SELF);
      for (unsigned int i = 0; i < n; ++i)
        exact(i) = std::sin(i / 10.);
      exact.compress(dealii::VectorOperation::insert);
      rhs.reinit(all, MPI_COMM_SELF);
      matrix.vmult(rhs, exact);
      solution.reinit(all, MPI_COMM_SELF);
    }

    double
    relative_error() const
    {
      Vector error(solution);
      error -= exact;
      return error.l2_norm() / exact.l2_norm();
    }

    dealii::TrilinosWrappers::SparsityPattern pattern;
    SparseMatrix                              matrix;
    Vector                                    exact, rhs, solution;
    Solver::LinearSolverSettings              settings;
  };

  // LU on a condition number below 3.5: round-off only.
  TEST_F(LinearSolverTest, DirectSolveRecoversTheManufacturedSolution)
  {
    settings.kind = LinearSolverKind::direct;
    const Solver::LinearSolveInfo info =
      Solver::solve_linear_system(settings, matrix, rhs, {}, solution);
    ASSERT_TRUE(info.success) << info.message;
    EXPECT_TRUE(info.used_direct);
    EXPECT_LT(relative_error(), 1e-12);
  }

  // GMRES stops at a relative residual of 1e-10; the error is at most the
  // condition number (< 3.5) times that.
  TEST_F(LinearSolverTest, IterativeSolveMeetsItsToleranceTimesTheCondition)
  {
    settings.kind               = LinearSolverKind::iterative;
    settings.relative_tolerance = 1e-10;
    const Solver::LinearSolveInfo info =
      Solver::solve_linear_system(settings, matrix, rhs, {}, solution);
    ASSERT_TRUE(info.success) << info.message;
    EXPECT_FALSE(info.used_direct);
    EXPECT_GT(info.n_iterations, 0u);
    EXPECT_LT(relative_error(), 3.5e-10);
  }

  // Rows 0 and 1 made identical: the matrix is singular. The solve reports
  // failure, does not throw, and leaves the solution as it was.
  TEST_F(LinearSolverTest, SingularMatrixFailsAndKeepsTheSolution)
  {
    matrix.set(1, 0, 4.);
    matrix.set(1, 1, -1.2);
    matrix.set(1, 2, 0.);
    matrix.compress(dealii::VectorOperation::insert);
    settings.kind = LinearSolverKind::direct;
    solution      = 7.;
    Solver::LinearSolveInfo info;
    ASSERT_NO_THROW(
      info = Solver::solve_linear_system(settings, matrix, rhs, {}, solution));
    EXPECT_FALSE(info.success);
    EXPECT_TRUE(Solver::has_only_finite_values(solution));
    EXPECT_EQ(solution(0), 7.);
    EXPECT_EQ(solution(n - 1), 7.);
  }

  TEST_F(LinearSolverTest, NonFiniteEntriesAreDetected)
  {
    EXPECT_TRUE(Solver::has_only_finite_values(exact));
    exact(n / 2) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(Solver::has_only_finite_values(exact));
    exact(n / 2) = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(Solver::has_only_finite_values(exact));
  }
} // namespace
