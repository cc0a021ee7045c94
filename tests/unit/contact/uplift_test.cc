// Stage 3 of the loading path: a block standing on the base follows a rigid
// motion of the base without any change of its joint forces.
#include <contact/contact_solver.h>
#include <contact/uplift.h>

#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>
#include <postprocess/increment_post_processor.h>

#include <cmath>

#include "block_mesh.h"
#include "test_scenes.h"

namespace
{
  using namespace FloorBlock;
  using namespace FloorBlock::Contact;

  constexpr dealii::types::boundary_id block_sides = 10, block_bottom = 11,
                                       block_top  = 12;
  constexpr dealii::types::boundary_id base_sides = 20, base_top = 21,
                                       base_bottom = 22;
  constexpr double density                         = 2500.; // kg/m^3
  constexpr double gravity_acceleration            = 9.81;  // m/s^2

  /**
   * A 1 m x 0.5 m block with gravity standing on a base (also the scene of
   * the load-step test): the base bottom follows @p uplift in @p n_uplift
   * increments after one gravity increment.
   */
  SolveResult
  solve_block_on_base(const UpliftSettings &uplift, const unsigned int n_uplift)
  {
    dealii::Triangulation<2> mesh;
    Testing::make_block_assembly({{0.,
                                   1.,
                                   0.,
                                   0.5,
                                   4,
                                   2,
                                   1,
                                   block_sides,
                                   block_sides,
                                   block_bottom,
                                   block_top},
                                  {0.,
                                   1.,
                                   -0.5,
                                   0.,
                                   4,
                                   2,
                                   2,
                                   base_sides,
                                   base_sides,
                                   base_bottom,
                                   base_top}},
                                 mesh);
    ContactProblem<2> scene;
    scene.model.laws.emplace(1, Testing::table_rock());
    scene.model.laws.emplace(2, Testing::table_rock());
    scene.model.densities[1]  = density;
    scene.model.gravity[1]    = -gravity_acceleration;
    SupportDefinition<2> base = Testing::fixed_support(base_bottom, true, true);
    base.moves_with_uplift    = true;
    scene.supports            = {base};
    JointDefinition<2> joint;
    joint.name                           = "bedding";
    joint.side_a                         = base_top;
    joint.side_b                         = block_bottom;
    joint.parameters.normal_stiffness    = 9e9;
    joint.parameters.shear_stiffness     = 6.7e9;
    joint.parameters.friction_angle      = 30. * M_PI / 180.;
    scene.joints                         = {joint};
    scene.uplift                         = uplift;
    scene.steps                          = {1, 0, n_uplift};
    const ContactSolverSettings settings = Testing::test_settings();
    ContactSolver<2>            solver(mesh, scene, settings);
    return Postprocess::solve_with_reports(solver, settings);
  }

  IncrementResult
  run_with_uplift(const UpliftSettings &uplift, IncrementResult &before_uplift)
  {
    const SolveResult result = solve_block_on_base(uplift, 2);
    EXPECT_EQ(result.increments.size(), 3u);
    before_uplift = result.increments.front();
    return result.increments.back();
  }

  void
  expect_rigid_follow(const UpliftSettings &uplift)
  {
    IncrementResult       before;
    const IncrementResult after = run_with_uplift(uplift, before);
    // A rigid translation of the support adds no strain: the block moves by
    // exactly the base displacement, the joint forces do not change. The
    // solution is the gravity state plus a rigid field, represented exactly,
    // so only the Newton tolerance (1e-12) and round-off remain: 1e-8.
    const dealii::Tensor<1, 2> expected =
      uplift_displacement(uplift, 1., dealii::Point<2>());
    const dealii::Tensor<1, 2> moved =
      after.motions.at(1).translation - before.motions.at(1).translation;
    EXPECT_LT((moved - expected).norm(), 1e-8 * expected.norm());
    const double weight = density * gravity_acceleration * 0.5;
    EXPECT_NEAR(after.joints.at(0).normal_force, weight, 1e-8 * weight);
    EXPECT_NEAR(after.joints.at(0).shear_force, 0., 1e-8 * weight);
    EXPECT_LT(after.balance.relative_imbalance, 1e-8);
  }

  TEST(Uplift, BlockFollowsVerticalTranslationOfTheBase)
  {
    UpliftSettings uplift;
    uplift.mode      = UpliftMotion::vertical_translation;
    uplift.magnitude = 2e-3; // m
    expect_rigid_follow(uplift);
  }

  TEST(Uplift, BlockFollowsDipTranslationOfTheBaseEitherWay)
  {
    UpliftSettings uplift;
    uplift.mode      = UpliftMotion::dip_translation;
    uplift.dip_angle = 10. * M_PI / 180.;
    for (const double magnitude : {2e-3, -2e-3}) // m, up-dip and down-dip
      {
        uplift.magnitude = magnitude;
        expect_rigid_follow(uplift);
      }
  }

  TEST(Uplift, TiltIsAnExactRotation)
  {
    UpliftSettings uplift;
    uplift.mode      = UpliftMotion::tilt;
    uplift.magnitude = 0.1; // rad
    uplift.pivot_x   = 1.;
    uplift.pivot_y   = 2.;
    const dealii::Point<2>     point(3., -1.);
    const dealii::Tensor<1, 2> moved =
      point + uplift_displacement(uplift, 1., point) - dealii::Point<2>(1., 2.);
    // Distance to the pivot is preserved and the angle grows by 0.1 rad.
    EXPECT_NEAR(moved.norm(), std::sqrt(4. + 9.), 1e-14);
    EXPECT_NEAR(std::atan2(moved[1], moved[0]) - std::atan2(-3., 2.),
                0.1,
                1e-14);
  }

  TEST(Uplift, ParabolaIsFlatBehindTheVertex)
  {
    UpliftSettings uplift;
    uplift.mode      = UpliftMotion::parabola;
    uplift.magnitude = 400.; // m, y = x^2/400
    EXPECT_NEAR(uplift_displacement(uplift, 0.5, dealii::Point<2>(6., 0.))[1],
                0.5 * 36. / 400.,
                1e-15);
    EXPECT_EQ(uplift_displacement(uplift, 1., dealii::Point<2>(-1., 0.))[1],
              0.);
  }

  // Load stepping: n increments of 1/n reach the end of a stage in exactly n
  // increments. Ten steps of 0.1 sum to 0.9999999999999999 in floating
  // point; that remainder must not become an eleventh, zero-length increment
  // (on refined meshes it made the default scene cycle in its last uplift
  // increment: every slipping pair is re-tested exactly on its Coulomb limit).
  TEST(LoadSteps, TenUpliftStepsAreTenIncrements)
  {
    UpliftSettings uplift;
    uplift.mode                     = UpliftMotion::vertical_translation;
    uplift.magnitude                = 1e-3; // m
    constexpr unsigned int n_uplift = 10;
    const SolveResult      result   = solve_block_on_base(uplift, n_uplift);
    ASSERT_EQ(result.increments.size(), 1u + n_uplift);
    for (unsigned int k = 1; k <= n_uplift; ++k)
      {
        EXPECT_EQ(result.increments[k].stage, Loading::LoadStage::uplift);
        // Summed steps: round-off of a few ulps, exactly 1 at the end.
        EXPECT_NEAR(result.increments[k].stage_factor,
                    static_cast<double>(k) / n_uplift,
                    1e-15);
      }
    EXPECT_EQ(result.increments.back().stage_factor, 1.);
  }
} // namespace
