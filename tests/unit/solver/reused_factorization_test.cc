// ReusedFactorization: stale LU factors as a GMRES preconditioner must give
// the answer of a fresh factorisation, use the stale factors only for a
// small change, and fail cleanly on a singular matrix.
#include <solver/reused_factorization.h>

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

  constexpr unsigned int n = 200;

  /**
   * Non-symmetric tridiagonal matrix (diagonal @p diagonal, off-diagonals
   * -1 and -1.2, like friction) plus @p shift on the diagonal of rows
   * [first, last). Its eigenvalues are diagonal - 2 sqrt(1.2) cos(k pi /
   * (n + 1)): diagonal 4 is well conditioned, diagonal 2 nearly singular.
   */
  void
  fill(SparseMatrix      &matrix,
       const unsigned int first,
       const unsigned int last,
       const double       shift,
       const double       diagonal = 4.)
  {
    matrix = 0.;
    for (unsigned int i = 0; i < n; ++i)
      {
        matrix.set(i, i, diagonal + (i >= first && i < last ? shift : 0.));
        if (i > 0)
          matrix.set(i, i - 1, -1.);
        if (i + 1 < n)
          matrix.set(i, i + 1, -1.2); // non-symmetric, like friction
      }
    matrix.compress(dealii::VectorOperation::insert);
  }

  class ReusedFactorizationTest : public ::testing::Test
  {
  protected:
    void
    SetUp() override
    {
      settings.max_reuse_iterations = 20;
    }

    FloorBlockTest::TridiagonalSystem system{n};
    SparseMatrix                     &matrix = system.matrix;
    Vector                           &rhs    = system.rhs;
    Vector                           &x      = system.x;
    Solver::LinearSolverSettings      settings;
  };

  TEST_F(ReusedFactorizationTest, SmallChangeReusesFactorsAndMeetsTolerance)
  {
    Solver::ReusedFactorization solver(settings);
    fill(matrix, 0, 0, 0.);
    ASSERT_TRUE(solver.solve(matrix, rhs, x).success);
    EXPECT_LT(relative_residual(matrix, x, rhs), 1e-10);
    EXPECT_EQ(solver.statistics().n_factorizations, 1u);

    // Three changed rows: rank 3, so GMRES on the old factors needs at most
    // four iterations in exact arithmetic.
    fill(matrix, 50, 53, 5.);
    const Solver::LinearSolveInfo info = solver.solve(matrix, rhs, x);
    ASSERT_TRUE(info.success);
    EXPECT_LT(relative_residual(matrix, x, rhs), 1e-10);
    EXPECT_EQ(solver.statistics().n_factorizations, 1u);
    EXPECT_EQ(solver.statistics().n_reused, 1u);
    EXPECT_LE(info.n_iterations, 4u + 2u); // margin for round-off
  }

  TEST_F(ReusedFactorizationTest, LargeChangeFactorisesAfresh)
  {
    Solver::ReusedFactorization solver(settings);
    fill(matrix, 0, 0, 0.);
    ASSERT_TRUE(solver.solve(matrix, rhs, x).success);
    fill(matrix, 0, 100, 5.); // 100 changed rows > 20 allowed iterations
    ASSERT_TRUE(solver.solve(matrix, rhs, x).success);
    EXPECT_LT(relative_residual(matrix, x, rhs), 1e-10);
    EXPECT_EQ(solver.statistics().n_factorizations, 2u);
    EXPECT_EQ(solver.statistics().n_reused, 0u);
    EXPECT_EQ(solver.statistics().n_accepted_above_tolerance, 0u);
  }

  TEST_F(ReusedFactorizationTest,
         IllConditionedMatrixIsNeverWorseThanFreshFactors)
  {
    // GMRES's own residual estimate claimed convergence on stale factors
    // here while the true residual was 4e-3: the solver must check.
    Solver::ReusedFactorization solver(settings);
    fill(matrix, 0, 0, 0., 2.);
    ASSERT_TRUE(solver.solve(matrix, rhs, x).success);
    fill(matrix, 50, 53, 5., 2.);
    ASSERT_TRUE(solver.solve(matrix, rhs, x).success);
    const double reused_residual = relative_residual(matrix, x, rhs);

    Solver::LinearSolverSettings fresh_only = settings;
    fresh_only.max_reuse_iterations         = 0;
    Solver::ReusedFactorization fresh(fresh_only);
    Vector                      y(x);
    ASSERT_TRUE(fresh.solve(matrix, rhs, y).success);
    EXPECT_LE(reused_residual,
              std::max(settings.relative_tolerance,
                       10. * relative_residual(matrix, y, rhs)));
  }

  TEST_F(ReusedFactorizationTest, ZeroReuseFactorisesEveryMatrix)
  {
    settings.max_reuse_iterations = 0;
    Solver::ReusedFactorization solver(settings);
    fill(matrix, 0, 0, 0.);
    ASSERT_TRUE(solver.solve(matrix, rhs, x).success);
    ASSERT_TRUE(solver.solve(matrix, rhs, x).success);
    EXPECT_EQ(solver.statistics().n_factorizations, 2u);
  }

  TEST_F(ReusedFactorizationTest, SingularMatrixFailsWithoutTouchingTheSolution)
  {
    Solver::ReusedFactorization solver(settings);
    matrix = 0.;
    for (unsigned int i = 0; i + 1 < n; ++i) // last row left empty
      matrix.set(i, i, 1.);
    matrix.compress(dealii::VectorOperation::insert);
    x                                  = 7.;
    const Solver::LinearSolveInfo info = solver.solve(matrix, rhs, x);
    EXPECT_FALSE(info.success);
    EXPECT_FALSE(info.message.empty());
    EXPECT_EQ(x(0), 7.);
  }
} // namespace

namespace
{
  // The same checks with UMFPACK as the LU (Solver::UmfpackFactors).
  TEST_F(ReusedFactorizationTest, UmfpackSolvesReusesAndRefactorises)
  {
    settings.direct_solver = Solver::DirectSolverKind::umfpack;
    Solver::ReusedFactorization solver(settings);
    fill(matrix, 0, 0, 0.);
    ASSERT_TRUE(solver.solve(matrix, rhs, x).success);
    EXPECT_LT(relative_residual(matrix, x, rhs), 1e-10);
    fill(matrix, 50, 53, 5.);
    ASSERT_TRUE(solver.solve(matrix, rhs, x).success);
    EXPECT_LT(relative_residual(matrix, x, rhs), 1e-10);
    EXPECT_EQ(solver.statistics().n_reused, 1u);
    fill(matrix, 0, 100, 5.);
    ASSERT_TRUE(solver.solve(matrix, rhs, x).success);
    EXPECT_LT(relative_residual(matrix, x, rhs), 1e-10);
    EXPECT_EQ(solver.statistics().n_factorizations, 2u);
  }

  TEST_F(ReusedFactorizationTest, UmfpackSingularMatrixFailsCleanly)
  {
    settings.direct_solver = Solver::DirectSolverKind::umfpack;
    Solver::ReusedFactorization solver(settings);
    matrix = 0.;
    for (unsigned int i = 0; i + 1 < n; ++i)
      matrix.set(i, i, 1.);
    matrix.compress(dealii::VectorOperation::insert);
    x                                  = 7.;
    const Solver::LinearSolveInfo info = solver.solve(matrix, rhs, x);
    EXPECT_FALSE(info.success);
    EXPECT_NE(info.message.find("UMFPACK"), std::string::npos) << info.message;
    EXPECT_EQ(x(0), 7.);
  }
} // namespace
