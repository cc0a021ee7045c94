// One block on a planar bedding: it slips iff tan(alpha) > tan(phi_h).
//
// The bedding falls away from the face (alpha < 0 in the chapter's sign
// convention), so the block tends to slide away from the face block and
// nothing but the bedding holds it: the face joint opens (ks < kn makes the
// elastic stick displacement point away from the face).

#include <gtest/gtest.h>

#include <cmath>

#include "scene_fixture.h"

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    constexpr double bedding_friction_degrees = 20.;

    RigidSolveResult
    solve_on_incline(const double dip_degrees)
    {
      const ModelDescription description =
        Testing::planar_scene(1,
                              -Testing::radians(dip_degrees),
                              Testing::radians(bedding_friction_degrees),
                              Testing::radians(bedding_friction_degrees));
      return Model(description).solve();
    }

    double
    block_weight()
    {
      const Geometry::AssemblyDescription geometry;
      return Testing::rock_density * Testing::standard_gravity *
             geometry.block_width * geometry.block_height;
    }
  } // namespace

  TEST(RigidIncline, StuckBlockCarriesWeightComponentInBeddingShear)
  {
    for (const double dip_degrees : {5., 15., 19.9})
      {
        SCOPED_TRACE(dip_degrees);
        const RigidSolveResult result = solve_on_incline(dip_degrees);
        ASSERT_EQ(result.status, SolveStatus::converged) << result.message;
        ASSERT_EQ(result.increments.size(), 1u);
        const IncrementReport  &increment = result.increments.back();
        const RigidJointReport &bedding =
          Testing::find_joint(increment, JointKind::bedding, 1);
        const RigidJointReport &face =
          Testing::find_joint(increment, JointKind::vertical, 1);
        const double dip = Testing::radians(dip_degrees);
        // Equilibrium along and across the bed; the Newton residual is below
        // 1e-12 of the load, so 1e-10 relative leaves round-off margin only.
        EXPECT_NEAR(bedding.shear_force / (block_weight() * std::sin(dip)),
                    1.,
                    1e-10);
        EXPECT_NEAR(bedding.normal_force / (block_weight() * std::cos(dip)),
                    1.,
                    1e-10);
        // Uniform traction (the weight passes through the base centre), so
        // the whole base sticks below the friction angle.
        EXPECT_EQ(bedding.counts.n_slip, 0u);
        EXPECT_EQ(bedding.counts.n_open, 0u);
        EXPECT_EQ(face.normal_force, 0.);
      }
  }

  TEST(RigidIncline, BlockSteeperThanFrictionHasNoEquilibrium)
  {
    for (const double dip_degrees : {20.1, 25., 40.})
      {
        SCOPED_TRACE(dip_degrees);
        const RigidSolveResult result = solve_on_incline(dip_degrees);
        EXPECT_EQ(result.status, SolveStatus::no_equilibrium) << result.message;
        EXPECT_EQ(result.failing_block, 1u);
        EXPECT_TRUE(result.increments.empty());
        EXPECT_FALSE(result.message.empty());
      }
  }

  TEST(RigidIncline, BlockLeaningOnFaceDoesNotSlideAway)
  {
    // Same bed rising away from the face (alpha > 0): the face block holds
    // the block even beyond the friction angle; bed-parallel balance with
    // a frictional face joint gives Q from slip_no_rotation's one-block
    // form, which the chain test checks; here only that it converges.
    const ModelDescription description =
      Testing::planar_scene(1,
                            Testing::radians(30.),
                            Testing::radians(bedding_friction_degrees),
                            Testing::radians(bedding_friction_degrees));
    const RigidSolveResult result = Model(description).solve();
    ASSERT_EQ(result.status, SolveStatus::converged) << result.message;
    EXPECT_GT(Testing::find_joint(result.increments.back(),
                                  JointKind::vertical,
                                  1)
                .normal_force,
              0.);
  }
} // namespace FloorBlock::RigidBlocks
