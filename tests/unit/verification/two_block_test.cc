// Two blocks side by side: the loaded block tilts against its neighbour so
// that the vertical joint closes only over its upper part. The set-up is the
// library's run_two_blocks_verification(), shared with `floorblock verify
// two-blocks`.
#include <verification/two_blocks_verification.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>

namespace
{
  using namespace FloorBlock;
  using namespace FloorBlock::Contact;
  using namespace FloorBlock::Verification;

  /** The library's run_two_blocks_verification(), shared with the CLI. */
  TwoBlocksResult
  run_two_blocks(const unsigned int cells_per_metre,
                 const JointLawKind law,
                 const double       joint_stiffness)
  {
    TwoBlocksSettings settings;
    settings.cells_per_metre = cells_per_metre;
    settings.law             = law;
    settings.joint_stiffness = joint_stiffness;
    return run_two_blocks_verification(settings);
  }

  constexpr double block_width = 1.; // m, of the library's case

  TEST(TwoBlocks, JointForceEqualsLateralLoadAndClosesAtTheTop)
  {
    const TwoBlocksResult outcome =
      run_two_blocks(4, JointLawKind::compliant, 9e9);
    // 4e5 Pa on the upper quarter (0.5 m) of the 2 m block, pinned so that
    // a changed default cannot make the checks below vacuous.
    EXPECT_DOUBLE_EQ(outcome.applied_lateral_force, 4e5 * 0.5);
    // Horizontal equilibrium of the right block on a frictionless base;
    // Newton tolerance 1e-12 relative, so 1e-8 holds with margin.
    EXPECT_NEAR(outcome.joint_normal_force,
                outcome.applied_lateral_force,
                1e-8 * outcome.applied_lateral_force);
    EXPECT_GT(outcome.closed_length, 0.);
    EXPECT_LT(outcome.closed_length, 0.75 * outcome.block_height);
    EXPECT_LT(outcome.relative_imbalance, 1e-8);
  }

  TEST(TwoBlocks, ClosedLengthConvergesUnderRefinement)
  {
    // The contact end is interpolated between nodes (make_joint_reports),
    // so the length changes by less than a cell per halving; from h = 1/4
    // to 1/8 it happens to change by only 0.4 % (measured 1.0885, 1.0842,
    // 1.0725, 1.0687 m at 1/4 ... 1/32), so the ladder starts at 1/8.
    const double coarse =
      run_two_blocks(8, JointLawKind::rigid, 0.).closed_length;
    const double medium =
      run_two_blocks(16, JointLawKind::rigid, 0.).closed_length;
    const double fine =
      run_two_blocks(32, JointLawKind::rigid, 0.).closed_length;
    std::cout << "closed length (m) at h = 1/8, 1/16, 1/32: " << coarse << " "
              << medium << " " << fine << std::endl;
    // Successive differences must shrink, and the last one be within one
    // fine cell (the node measure gave 1.125, 1.0625, 1.09375, 1.078125 m:
    // steps of a quarter of the coarser cell).
    EXPECT_LT(std::abs(fine - medium), std::abs(medium - coarse) + 1e-12);
    EXPECT_LT(std::abs(fine - medium), block_width / 32.);
  }

  TEST(TwoBlocks, StiffCompliantLawApproachesRigidLaw)
  {
    const TwoBlocksResult rigid = run_two_blocks(8, JointLawKind::rigid, 0.);
    const TwoBlocksResult stiff =
      run_two_blocks(8, JointLawKind::compliant, 1e14);
    std::cout << "rigid vs compliant(1e14): rotation " << rigid.right_rotation
              << " " << stiff.right_rotation << ", averaged peak "
              << rigid.averaged_peak << " " << stiff.averaged_peak
              << ", closed length " << rigid.closed_length << " "
              << stiff.closed_length << std::endl;
    // The acceptance bound: within 1 %.
    EXPECT_NEAR(stiff.right_rotation,
                rigid.right_rotation,
                0.01 * std::abs(rigid.right_rotation));
    EXPECT_NEAR(stiff.averaged_peak,
                rigid.averaged_peak,
                0.01 * rigid.averaged_peak);
    EXPECT_NEAR(stiff.joint_normal_force,
                rigid.joint_normal_force,
                1e-8 * rigid.applied_lateral_force);
  }
} // namespace

namespace
{
  TEST(TwoBlocks, CompliantLawConvergesToRigidAsStiffnessGrows)
  {
    const double rigid =
      run_two_blocks(8, JointLawKind::rigid, 0.).right_rotation;
    double previous_error = std::numeric_limits<double>::max();
    for (const double stiffness : {1e10, 1e11, 1e12, 1e13})
      {
        const double error = std::abs(
          run_two_blocks(8, JointLawKind::compliant, stiffness).right_rotation -
          rigid);
        std::cout << "kn = ks = " << stiffness << " Pa/m: rotation error "
                  << error / std::abs(rigid) << std::endl;
        // Joint compliance adds rotation of order (force / kn) / lever arm,
        // so the error must fall as the stiffness grows.
        EXPECT_LT(error, previous_error);
        previous_error = error;
      }
  }
} // namespace

namespace
{
  // Hanging-node constraints together with contact: both joint sides
  // refined alike near the top corner (corner_refinements), so the joint's
  // hanging nodes pair with hanging nodes. Horizontal equilibrium must hold
  // as on the conforming mesh, and the closed length must agree with the
  // uniformly refined mesh of the same corner cell size to within a cell.
  TEST(TwoBlocks, HangingNodesAtTheJointKeepEquilibrium)
  {
    TwoBlocksSettings settings;
    settings.cells_per_metre    = 8;
    settings.corner_refinements = 2; // corner cells 1/32 m
    const TwoBlocksResult local = run_two_blocks_verification(settings);
    EXPECT_NEAR(local.joint_normal_force,
                local.applied_lateral_force,
                1e-8 * local.applied_lateral_force);
    EXPECT_LT(local.relative_imbalance, 1e-10);

    settings.corner_refinements   = 0;
    const TwoBlocksResult coarse  = run_two_blocks_verification(settings);
    settings.cells_per_metre      = 32;
    const TwoBlocksResult uniform = run_two_blocks_verification(settings);
    std::cout << "closed length: local refinement " << local.closed_length
              << " m, uniform 1/8 " << coarse.closed_length
              << " m, uniform 1/32 " << uniform.closed_length << " m; rotation "
              << local.right_rotation << " / " << coarse.right_rotation << " / "
              << uniform.right_rotation << std::endl;
    // The joint is resolved as on the uniform 1/32 mesh (within one of its
    // cells); the rotation also depends on the bulk's far field, which the
    // corner refinement leaves at 1/8: it must be no further from the
    // 1/32 value than the unrefined 1/8 mesh is.
    EXPECT_NEAR(local.closed_length, uniform.closed_length, 1. / 32.);
    EXPECT_LE(std::abs(local.right_rotation - uniform.right_rotation),
              std::abs(coarse.right_rotation - uniform.right_rotation));
  }
} // namespace
