// The tool shall evaluate rotation with vertical slip (6.39-6.46), checked
// against an independent global solve and the chapter's closed form.

#include <analytic/rotation_vertical_slip.h>
#include <analytic/slip_no_rotation.h>

#include <gtest/gtest.h>

#include "rotated_chain_system.h"
#include "test_chains.h"

using namespace FloorBlock;
using namespace FloorBlock::Analytic;
using namespace FloorBlock::AnalyticTest;

TEST(RotationVerticalSlip, ShallMatchIndependentEquilibriumSolveOnCurvedBedding)
{
  const BlockChain           chain  = irregular_chain();
  const ChainForces          forces = rotation_vertical_slip(chain);
  const RotatedChainSolution solution =
    solve_rotated_chain_with_joint_slip(chain);
  for (std::size_t block = 0; block < chain.n_blocks(); ++block)
    {
      EXPECT_LT(relative_difference(forces.lateral_force[block],
                                    solution.lateral_force[block]),
                solve_tolerance);
      EXPECT_LT(relative_difference(forces.normal_force[block],
                                    solution.normal_force[block]),
                solve_tolerance);
      EXPECT_LT(std::abs(forces.normal_force_offset[block] -
                         solution.normal_force_offset[block]) /
                  chain.block_width,
                solve_tolerance);
    }
}

TEST(RotationVerticalSlip, ShallReduceToEquation6_46OnPlanarBedding)
{
  BlockChain   chain = irregular_chain();
  const double alpha = degrees(7.);
  chain.inclination.assign(chain.n_blocks(), alpha);
  const ChainForces forces   = rotation_vertical_slip(chain);
  const double      tan_h    = std::tan(chain.bedding_friction);
  const double      tan_v    = std::tan(chain.vertical_friction);
  double            expected = 0.;
  for (std::size_t block = 0; block < chain.n_blocks(); ++block)
    {
      expected += (chain.weight[block] + chain.support_load[block]) *
                  (std::sin(alpha) + tan_h * std::cos(alpha)) /
                  (1. - tan_h * tan_v);
      EXPECT_LT(relative_difference(forces.lateral_force[block], expected),
                solve_tolerance);
    }
}

TEST(RotationVerticalSlip, ShallCoincideWithSlipWithoutRotationOnLevelBedding)
{
  // At alpha = 0 upright and rotated blocks are the same body.
  BlockChain chain = irregular_chain();
  chain.inclination.assign(chain.n_blocks(), 0.);
  const ChainForces rotated = rotation_vertical_slip(chain);
  const ChainForces upright = slip_no_rotation(chain);
  for (std::size_t block = 0; block < chain.n_blocks(); ++block)
    EXPECT_LT(relative_difference(rotated.lateral_force[block],
                                  upright.lateral_force[block]),
              solve_tolerance);
}

TEST(RotationVerticalSlip, ShallReportSelfLockingWhenTheFrictionAnglesSumTo90)
{
  const ChainForces forces = rotation_vertical_slip(uniform_chain(
    3, 49.05e3, 0., degrees(3.), 1., 2., degrees(45.), degrees(45.)));
  EXPECT_EQ(forces.status, Status::self_locking);
  EXPECT_TRUE(forces.lateral_force.empty());
}

TEST(RotationVerticalSlip, ShallReportANormalForceOffTheBaseForSlenderBlocks)
{
  // Block 1 on level bedding: N = W / (1 - tan phi_h tan phi_v), and the
  // moment about the face-side top corner puts it at
  // W L / (2 N) + H tan(phi_h) = 0.5 (1 - 0.21) + 2 tan 30 = 1.55 m from the
  // face-side edge, beyond the 1 m base.
  const double tan_h = std::tan(degrees(30.)), tan_v = std::tan(degrees(20.));
  const ChainForces forces = rotation_vertical_slip(
    uniform_chain(2, 49.05e3, 0., 0., 1., 2., degrees(30.), degrees(20.)));
  EXPECT_EQ(forces.status, Status::normal_force_outside_base);
  EXPECT_EQ(forces.failing_block, 1u);
  EXPECT_NEAR(forces.normal_force_offset[0],
              1. - (0.5 * (1. - tan_h * tan_v) + 2. * tan_h),
              1e-12);
}
