// The tool shall evaluate the no-rotation mechanism (6.1-6.25) and its
// rotation criterion, checked against an independent equilibrium solve.

#include <analytic/centroid_heights.h>
#include <analytic/slip_no_rotation.h>

#include <gtest/gtest.h>

#include "dense_solver.h"
#include "test_chains.h"

using namespace FloorBlock;
using namespace FloorBlock::Analytic;
using namespace FloorBlock::AnalyticTest;

namespace
{
  /**
   * Horizontal and vertical force balance of every upright block, global
   * axes (x away from the face, y up), unknowns [Q_1..Q_n, N_1..N_n]. The
   * library uses the bed-normal projection and a recursion instead.
   */
  std::vector<double>
  solve_upright_chain(const BlockChain &chain)
  {
    const unsigned int n_blocks     = chain.n_blocks();
    const double       tan_bedding  = std::tan(chain.bedding_friction);
    const double       tan_vertical = std::tan(chain.vertical_friction);
    DenseSystem        system(2 * n_blocks);
    for (unsigned int block = 0; block < n_blocks; ++block)
      {
        const unsigned int x_row = 2 * block, y_row = 2 * block + 1;
        const unsigned int q_own = block, n_own = n_blocks + block;
        const double       sin_a = std::sin(chain.inclination[block]);
        const double       cos_a = std::cos(chain.inclination[block]);
        // Joint i pushes block i away from the face and drags it down.
        system.add(x_row, q_own, 1.);
        system.add(y_row, q_own, -tan_vertical);
        if (block > 0)
          {
            system.add(x_row, q_own - 1, -1.);
            system.add(y_row, q_own - 1, tan_vertical);
          }
        // Base normal (-sin a, cos a) and friction -(cos a, sin a) tan phi_h.
        system.add(x_row, n_own, -sin_a - tan_bedding * cos_a);
        system.add(y_row, n_own, cos_a - tan_bedding * sin_a);
        system.add_rhs(y_row, chain.weight[block] + chain.support_load[block]);
      }
    return system.solve();
  }
} // namespace

TEST(SlipNoRotation, ShallMatchIndependentEquilibriumSolveOnCurvedBedding)
{
  const BlockChain          chain    = irregular_chain();
  const ChainForces         forces   = slip_no_rotation(chain);
  const std::vector<double> solution = solve_upright_chain(chain);
  ASSERT_EQ(forces.status, Status::ok);
  const std::size_t n_blocks = chain.n_blocks();
  for (std::size_t block = 0; block < n_blocks; ++block)
    {
      EXPECT_LT(relative_difference(forces.lateral_force[block],
                                    solution[block]),
                solve_tolerance);
      EXPECT_LT(relative_difference(forces.normal_force[block],
                                    solution[n_blocks + block]),
                solve_tolerance);
    }
}

TEST(SlipNoRotation, ShallReduceToTheLinearFormula6_23ForEqualBlocks)
{
  const double weight = 49.05e3, support_load = 120.e3;
  const double alpha = degrees(8.), phi_h = degrees(20.), phi_v = degrees(25.);
  const BlockChain chain =
    uniform_chain(6, weight, support_load, alpha, 1., 2., phi_h, phi_v);
  const ChainForces forces = slip_no_rotation(chain);
  ASSERT_EQ(forces.status, Status::ok);
  // Eq. 6.23 as printed: Q_n = n (W + P) cos a / ((sin a + tan phi_h cos a)^-1
  //                                               - (sin a + tan phi_v cos a))
  const double denominator =
    1. / (std::sin(alpha) + std::tan(phi_h) * std::cos(alpha)) -
    (std::sin(alpha) + std::tan(phi_v) * std::cos(alpha));
  for (std::size_t block = 0; block < chain.n_blocks(); ++block)
    EXPECT_LT(relative_difference(forces.lateral_force[block],
                                  (block + 1) * (weight + support_load) *
                                    std::cos(alpha) / denominator),
              solve_tolerance);
}

TEST(SlipNoRotation, ShallNeedWTanAlphaPlusPhiForOneBlockWithoutJointFriction)
{
  // Classic wedge result: a block pushed up a slope needs W tan(alpha + phi).
  const double      weight = 30.e3, alpha = degrees(12.), phi_h = degrees(22.);
  const ChainForces forces =
    slip_no_rotation(uniform_chain(1, weight, 0., alpha, 1., 2., phi_h, 0.));
  ASSERT_EQ(forces.status, Status::ok);
  EXPECT_LT(relative_difference(forces.lateral_force[0],
                                weight * std::tan(alpha + phi_h)),
            solve_tolerance);
}

TEST(SlipNoRotation, ShallGiveNoThrustOnFrictionlessLevelBedding)
{
  const ChainForces forces =
    slip_no_rotation(uniform_chain(4, 50.e3, 10.e3, 0., 1., 2., 0., 0.3));
  ASSERT_EQ(forces.status, Status::ok);
  for (const double lateral_force : forces.lateral_force)
    EXPECT_EQ(lateral_force, 0.);
  EXPECT_DOUBLE_EQ(forces.normal_force[0], 60.e3);
}

TEST(SlipNoRotation, ShallScaleLinearlyWithLoadsAndNotWithBlockSize)
{
  // Dimensional check: Q is a force, linear in W and P, independent of L, H.
  const BlockChain chain  = irregular_chain();
  BlockChain       scaled = chain;
  for (std::size_t block = 0; block < chain.n_blocks(); ++block)
    {
      scaled.weight[block] *= 3.;
      scaled.support_load[block] *= 3.;
    }
  scaled.block_width *= 5.;
  scaled.block_height *= 5.;
  const ChainForces original = slip_no_rotation(chain);
  const ChainForces tripled  = slip_no_rotation(scaled);
  for (std::size_t block = 0; block < chain.n_blocks(); ++block)
    EXPECT_LT(relative_difference(tripled.lateral_force[block],
                                  3. * original.lateral_force[block]),
              solve_tolerance);
}

TEST(SlipNoRotation, ShallReportSelfLockingInsteadOfInfiniteThrust)
{
  // a c = (sin 30 + tan 45 cos 30)^2 = 1.87 > 1: no finite Q slides the chain.
  const ChainForces forces = slip_no_rotation(uniform_chain(
    3, 50.e3, 0., degrees(30.), 1., 2., degrees(45.), degrees(45.)));
  EXPECT_EQ(forces.status, Status::self_locking);
  EXPECT_EQ(forces.failing_block, 1u);
  EXPECT_TRUE(forces.lateral_force.empty());
}

TEST(SlipNoRotation, ShallReportOpeningJointsOnBeddingDippingToTheFace)
{
  // alpha = -30 deg < -phi_h: the blocks slide away from the face by
  // themselves, the joints would need tension.
  const ChainForces forces = slip_no_rotation(uniform_chain(
    3, 50.e3, 0., degrees(-30.), 1., 2., degrees(10.), degrees(20.)));
  EXPECT_EQ(forces.status, Status::joint_opens);
  EXPECT_EQ(forces.failing_block, 1u);
  ASSERT_EQ(forces.lateral_force.size(), 3u);
  EXPECT_LT(forces.lateral_force[0], 0.);
}

TEST(SlipNoRotation, ShallRejectInvalidInputsWithAStatus)
{
  BlockChain negative_weight = irregular_chain();
  negative_weight.weight[2]  = -1.;
  BlockChain short_vector    = irregular_chain();
  short_vector.inclination.pop_back();
  BlockChain vertical_friction        = irregular_chain();
  vertical_friction.vertical_friction = M_PI_2;
  BlockChain not_a_number             = irregular_chain();
  not_a_number.block_height           = std::nan("");
  for (const BlockChain &chain : {negative_weight,
                                  short_vector,
                                  vertical_friction,
                                  not_a_number,
                                  BlockChain()})
    {
      EXPECT_EQ(slip_no_rotation(chain).status, Status::invalid_input);
      EXPECT_TRUE(slip_no_rotation(chain).lateral_force.empty());
    }
}

TEST(CentroidHeights, ShallReproduceEquation6_20ForEqualUnloadedBlocks)
{
  const double alpha = degrees(6.), phi_h = degrees(18.), phi_v = degrees(28.);
  const double width = 1.;
  const BlockChain chain =
    uniform_chain(6, 49.05e3, 0., alpha, width, 2., phi_h, phi_v);
  const CentroidHeights heights =
    centroid_heights(chain, slip_no_rotation(chain).lateral_force);
  ASSERT_EQ(heights.status, Status::ok);
  const double denominator =
    1. / (std::sin(alpha) + std::tan(phi_h) * std::cos(alpha)) -
    (std::sin(alpha) + std::tan(phi_v) * std::cos(alpha));
  for (std::size_t block = 0; block < chain.n_blocks(); ++block)
    {
      // Eq. 6.20 with the chapter's i = block + 1.
      const double chapter_i = block + 1.;
      const double expected  = width * denominator / (2. * std::cos(alpha)) +
                              (chapter_i + 1.) * width * std::tan(phi_v) / 2.;
      EXPECT_LT(relative_difference(heights.centroid_height[block], expected),
                solve_tolerance);
    }
}

TEST(CentroidHeights, ShallReproduceCorrected6_25WithLoadAtTheFaceSideEdge)
{
  // Printed 6.25 has a spurious factor 1/2 in its first term (README.md);
  // with P at the face-side edge (position 1) the derivation gives
  // h_i = L (P + W/2) D / ((W + P) cos a) + (i + 1) L tan(phi_v) / 2.
  const double weight = 49.05e3, support_load = 200.e3;
  const double alpha = degrees(4.), phi_h = degrees(15.), phi_v = degrees(35.);
  const double width = 1.;
  BlockChain   chain =
    uniform_chain(4, weight, support_load, alpha, width, 2., phi_h, phi_v);
  chain.support_load_position = 1.;
  const CentroidHeights heights =
    centroid_heights(chain, slip_no_rotation(chain).lateral_force);
  const double denominator =
    1. / (std::sin(alpha) + std::tan(phi_h) * std::cos(alpha)) -
    (std::sin(alpha) + std::tan(phi_v) * std::cos(alpha));
  for (std::size_t block = 0; block < chain.n_blocks(); ++block)
    {
      const double chapter_i = block + 1.;
      const double expected  = width * (support_load + weight / 2.) *
                                denominator /
                                ((weight + support_load) * std::cos(alpha)) +
                              (chapter_i + 1.) * width * std::tan(phi_v) / 2.;
      EXPECT_LT(relative_difference(heights.centroid_height[block], expected),
                solve_tolerance);
    }
}

TEST(CentroidHeights, ShallSatisfyTheMomentBalanceAboutTheBlockCentre)
{
  // Printed 6.21 (with N_{i+1} for N_i) is this balance about the block
  // centre, small-angle form; a different moment point than the library's.
  BlockChain chain = irregular_chain();
  chain.inclination.assign(chain.n_blocks(), 0.);
  const ChainForces     forces  = slip_no_rotation(chain);
  const CentroidHeights heights = centroid_heights(chain, forces.lateral_force);
  const double          width = chain.block_width, height = chain.block_height;
  const double          tan_v = std::tan(chain.vertical_friction);
  const double          tan_h = std::tan(chain.bedding_friction);
  for (std::size_t block = 1; block < chain.n_blocks(); ++block)
    {
      const double q_own  = forces.lateral_force[block];
      const double q_away = forces.lateral_force[block - 1];
      const double normal = forces.normal_force[block];
      const double left =
        q_own * (heights.centroid_height[block] - height / 2.) +
        normal * height / 2. * tan_h;
      const double right =
        (q_own + q_away) * width / 2. * tan_v + normal * width / 2. +
        q_away * (heights.centroid_height[block - 1] - height / 2.) +
        chain.support_load[block] * (chain.support_load_position - 0.5) * width;
      EXPECT_LT(relative_difference(left, right), solve_tolerance);
    }
}

TEST(CentroidHeights, ShallFlagRotationWhenTheResultantRisesAboveTheBlock)
{
  // Low bedding friction, high joint friction: h_1 = L D / 2 + L tan phi_v
  // = 0.5 (1/tan 10 - tan 35) + tan 35 = 3.19 m > H = 2 m.
  const BlockChain chain =
    uniform_chain(3, 49.05e3, 0., 0., 1., 2., degrees(10.), degrees(35.));
  const CentroidHeights heights =
    centroid_heights(chain, slip_no_rotation(chain).lateral_force);
  EXPECT_EQ(heights.first_rotating_block, 1u);
  EXPECT_NEAR(heights.centroid_height[0],
              0.5 * (1. / std::tan(degrees(10.)) - std::tan(degrees(35.))) +
                std::tan(degrees(35.)),
              1e-12);
  EXPECT_LT(heights.rotation_margin[0], 0.);
  // High bedding friction: h_1 = 0.5 (1/tan 30 - tan 15) + tan 15 = 1.02 m.
  const BlockChain stiff =
    uniform_chain(1, 49.05e3, 0., 0., 1., 2., degrees(30.), degrees(15.));
  const CentroidHeights upright =
    centroid_heights(stiff, slip_no_rotation(stiff).lateral_force);
  EXPECT_EQ(upright.first_rotating_block, 0u);
  EXPECT_GT(upright.rotation_margin[0], 0.);
}

TEST(CentroidHeights, ShallReportAZeroLateralForceInsteadOfDividingByIt)
{
  const BlockChain      chain = uniform_chain(2, 50.e3, 0., 0., 1., 2., 0., 0.);
  const CentroidHeights heights =
    centroid_heights(chain, slip_no_rotation(chain).lateral_force);
  EXPECT_EQ(heights.status, Status::joint_opens);
  EXPECT_TRUE(heights.centroid_height.empty());
  EXPECT_EQ(centroid_heights(chain, {1.}).status, Status::invalid_input);
}
