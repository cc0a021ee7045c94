// The tool shall evaluate rotation without vertical slip (6.26-6.38) from
// the re-derived recursion, checked against an independent global solve.

#include <analytic/rotation_no_vertical_slip.h>

#include <gtest/gtest.h>

#include <numeric>

#include "rotated_chain_system.h"
#include "test_chains.h"

using namespace FloorBlock;
using namespace FloorBlock::Analytic;
using namespace FloorBlock::AnalyticTest;

namespace
{
  void
  expect_same_forces(const ChainForces          &forces,
                     const RotatedChainSolution &solution)
  {
    ASSERT_EQ(forces.lateral_force.size(), solution.lateral_force.size());
    for (std::size_t block = 0; block < forces.lateral_force.size(); ++block)
      {
        // V can pass through zero: compare it against the block's Q scale.
        const double scale = std::abs(solution.lateral_force[block]);
        EXPECT_LT(relative_difference(forces.lateral_force[block],
                                      solution.lateral_force[block]),
                  solve_tolerance);
        EXPECT_LT(relative_difference(forces.normal_force[block],
                                      solution.normal_force[block]),
                  solve_tolerance);
        EXPECT_LT(std::abs(forces.joint_shear[block] -
                           solution.joint_shear[block]) /
                    scale,
                  solve_tolerance);
      }
  }
} // namespace

TEST(RotationNoVerticalSlip,
     ShallMatchIndependentEquilibriumSolveOnCurvedBedding)
{
  // Stubby blocks (H tan phi_h well below L) so the recursion is stable.
  BlockChain chain         = irregular_chain();
  chain.block_height       = 1.5;
  const ChainForces forces = rotation_no_vertical_slip(chain);
  expect_same_forces(forces, solve_rotated_chain_without_joint_slip(chain));
}

TEST(RotationNoVerticalSlip, ShallGiveQnEqualSumNTanPhiOnLevelBedding)
{
  // Eq. 6.28: on level bedding Q_n = tan(phi_h) sum N_i, and the vertical
  // balance of the whole chain gives sum N_i = sum (W_i + P_i) + V_n.
  BlockChain chain = irregular_chain();
  chain.inclination.assign(chain.n_blocks(), 0.);
  const ChainForces forces = rotation_no_vertical_slip(chain);
  const double      sum_normal =
    std::accumulate(forces.normal_force.begin(), forces.normal_force.end(), 0.);
  const double sum_loads =
    std::accumulate(chain.weight.begin(), chain.weight.end(), 0.) +
    std::accumulate(chain.support_load.begin(), chain.support_load.end(), 0.);
  EXPECT_LT(relative_difference(forces.lateral_force.back(),
                                sum_normal * std::tan(chain.bedding_friction)),
            solve_tolerance);
  EXPECT_LT(relative_difference(sum_normal,
                                sum_loads + forces.joint_shear.back()),
            solve_tolerance);
}

TEST(RotationNoVerticalSlip,
     ShallGiveEquation6_30bForTheFirstBlockOnLevelBedding)
{
  // 6.29/6.30b: N_1 = 0.5 L (W + P) / (L - H tan phi_h), Q_1 = N_1 tan phi_h.
  const double      weight = 49.05e3, support = 20.e3, width = 1., height = 2.;
  const double      phi_h  = degrees(12.);
  const ChainForces forces = rotation_no_vertical_slip(
    uniform_chain(1, weight, support, 0., width, height, phi_h, degrees(40.)));
  const double normal =
    0.5 * width * (weight + support) / (width - height * std::tan(phi_h));
  EXPECT_LT(relative_difference(forces.normal_force[0], normal),
            solve_tolerance);
  EXPECT_LT(relative_difference(forces.lateral_force[0],
                                normal * std::tan(phi_h)),
            solve_tolerance);
}

TEST(RotationNoVerticalSlip,
     ShallReportTheSingularityOf6_29ForTheChaptersBlocks)
{
  // H = 2 m, L = 1 m: L - H tan(phi_h) <= 0 from phi_h = atan(1/2) = 26.57 deg.
  for (const double phi_h : {std::atan(0.5), degrees(30.), degrees(35.)})
    {
      const ChainForces forces = rotation_no_vertical_slip(uniform_chain(
        6, 49.05e3, 0., degrees(2.), 1., 2., phi_h, degrees(30.)));
      EXPECT_EQ(forces.status, Status::rotation_denominator_nonpositive);
      EXPECT_TRUE(forces.lateral_force.empty());
    }
  EXPECT_NE(
    rotation_no_vertical_slip(
      uniform_chain(
        6, 49.05e3, 0., degrees(2.), 1., 2., degrees(26.), degrees(30.)))
      .status,
    Status::rotation_denominator_nonpositive);
}

TEST(RotationNoVerticalSlip, ShallReportWhenJointFrictionCannotHoldTheShear)
{
  // Level bedding, phi_h = 10 deg: V_1 = N_1 - W = W (0.5/(1 - 2 tan 10) - 1)
  // = -0.227 W but Q_1 tan(phi_v) = 0.136 W tan(phi_v) is smaller for any
  // phi_v < 59 deg.
  const ChainForces forces = rotation_no_vertical_slip(
    uniform_chain(3, 49.05e3, 0., 0., 1., 2., degrees(10.), degrees(35.)));
  EXPECT_EQ(forces.status, Status::vertical_friction_exceeded);
  EXPECT_EQ(forces.failing_block, 1u);
  EXPECT_EQ(forces.lateral_force.size(), 3u);
}

TEST(RotationNoVerticalSlip, ShallAcceptAChainWhoseJointsStick)
{
  // tan(phi_h) = L / (2 H) makes N_1 = 0.5 L W / (L - H tan phi_h) = W on
  // level bedding, so V_1 = 0, and then every block repeats block 1.
  const ChainForces forces = rotation_no_vertical_slip(
    uniform_chain(4, 49.05e3, 0., 0., 1., 2., std::atan(0.25), degrees(30.)));
  EXPECT_EQ(forces.status, Status::ok);
  for (const double shear : forces.joint_shear)
    EXPECT_NEAR(shear, 0., 1e-9);
}

TEST(RotationNoVerticalSlip, ShallDependOnBlockSizeOnlyThroughTheRatioHOverL)
{
  BlockChain chain   = irregular_chain();
  chain.block_height = 1.5;
  BlockChain scaled  = chain;
  scaled.block_width *= 4.;
  scaled.block_height *= 4.;
  const ChainForces original = rotation_no_vertical_slip(chain);
  const ChainForces larger   = rotation_no_vertical_slip(scaled);
  for (std::size_t block = 0; block < chain.n_blocks(); ++block)
    EXPECT_LT(relative_difference(larger.lateral_force[block],
                                  original.lateral_force[block]),
              solve_tolerance);
}
