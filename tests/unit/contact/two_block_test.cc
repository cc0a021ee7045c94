// Two blocks side by side: the loaded block tilts against its neighbour so
// that the vertical joint closes only over its upper part.
#include "block_mesh.h"
#include "test_scenes.h"

#include <contact/contact_solver.h>

#include <gtest/gtest.h>

#include <deal.II/grid/tria.h>

#include <cmath>
#include <limits>

namespace
{
  using namespace FloorBlock;
  using namespace FloorBlock::Contact;

  // Left block (fixed, like the face block), right block, base under it.
  constexpr dealii::types::boundary_id left_outer = 11, left_joint = 12,
                                       left_bottom = 13, left_top = 14;
  constexpr dealii::types::boundary_id right_joint = 21, right_outer = 22,
                                       right_bottom = 23, right_top = 24,
                                       right_outer_upper = 25;
  constexpr dealii::types::boundary_id base_sides = 31, base_top = 32,
                                       base_bottom = 33;
  constexpr double block_height   = 2.;    // m
  constexpr double block_width    = 1.;    // m
  constexpr double loaded_from_y  = 1.5;   // m, lateral load on the upper quarter
  constexpr double lateral_pressure = 4e5; // Pa
  constexpr double density        = 2500.; // kg/m^3
  constexpr double gravity_acceleration = 9.81; // m/s^2

  struct TwoBlockOutcome
  {
    double joint_normal_force = 0.;
    double closed_length      = 0.;
    double averaged_peak      = 0.;
    double right_rotation     = 0.;
    double imbalance          = 0.;
  };

  TwoBlockOutcome
  run_two_blocks(const unsigned int cells_per_metre,
                 const JointLawKind law,
                 const double       joint_stiffness)
  {
    const unsigned int n_x = cells_per_metre;
    const unsigned int n_y = 2 * cells_per_metre;
    dealii::Triangulation<2> mesh;
    Testing::make_block_assembly(
      {{-block_width, 0., 0., block_height, n_x, n_y, 1, left_outer, left_joint, left_bottom, left_top},
       {0., block_width, 0., block_height, n_x, n_y, 2, right_joint, right_outer, right_bottom, right_top, loaded_from_y, right_outer_upper},
       {0., block_width, -0.5, 0., n_x, n_x / 2, 3, base_sides, base_sides, base_bottom, base_top}},
      mesh);
    SceneDefinition<2> scene;
    for (const dealii::types::material_id body : {1, 2, 3})
      scene.model.laws.emplace(body, Testing::table_rock());
    scene.model.densities[2]              = density;
    scene.model.gravity[1]                = -gravity_acceleration;
    scene.model.pressures[right_outer_upper] = lateral_pressure;
    scene.supports = {Testing::fixed_support(left_outer, true, true),
                      Testing::fixed_support(left_bottom, true, true),
                      Testing::fixed_support(base_bottom, true, true)};
    JointDefinition<2> vertical;
    vertical.name                        = "vertical";
    vertical.side_a                      = left_joint;
    vertical.side_b                      = right_joint;
    vertical.law                         = law;
    vertical.parameters.normal_stiffness = joint_stiffness;
    vertical.parameters.shear_stiffness  = joint_stiffness;
    vertical.parameters.friction_angle   = 30. * M_PI / 180.;
    JointDefinition<2> bedding           = vertical;
    bedding.name                         = "bedding";
    bedding.side_a                       = base_top;
    bedding.side_b                       = right_bottom;
    // Frictionless bedding: the lateral load can only go into the joint.
    bedding.parameters.friction_angle = 0.;
    scene.joints                      = {vertical, bedding};
    // Gravity and lateral load together (a gravity stage of 0 increments
    // applies gravity with the first pressure increment): under gravity
    // alone, frictionless bedding and an opening joint would leave the
    // right block a horizontal mechanism with no unique answer.
    scene.steps                       = {0, 2, 0};
    ContactSolver     solver(mesh, scene, Testing::test_settings());
    const SolveResult result = solver.run();
    const IncrementResult &last = result.increments.back();
    TwoBlockOutcome        outcome;
    outcome.joint_normal_force = last.joints.at(0).normal_force;
    outcome.closed_length      = last.joints.at(0).closed_length;
    outcome.averaged_peak      = last.joints.at(0).averaged_peak_normal_stress;
    outcome.right_rotation     = last.motions.at(2).rotation;
    outcome.imbalance          = last.balance.relative_imbalance;
    return outcome;
  }

  const double applied_lateral_force =
    lateral_pressure * (block_height - loaded_from_y); // N/m

  TEST(TwoBlocks, JointForceEqualsLateralLoadAndClosesAtTheTop)
  {
    const TwoBlockOutcome outcome =
      run_two_blocks(4, JointLawKind::compliant, 9e9);
    // Horizontal equilibrium of the right block on a frictionless base;
    // Newton tolerance 1e-12 relative, so 1e-8 holds with margin.
    EXPECT_NEAR(outcome.joint_normal_force, applied_lateral_force,
                1e-8 * applied_lateral_force);
    EXPECT_GT(outcome.closed_length, 0.);
    EXPECT_LT(outcome.closed_length, 0.75 * block_height);
    EXPECT_LT(outcome.imbalance, 1e-8);
  }

  TEST(TwoBlocks, ClosedLengthConvergesUnderRefinement)
  {
    const double coarse = run_two_blocks(4, JointLawKind::rigid, 0.).closed_length;
    const double medium = run_two_blocks(8, JointLawKind::rigid, 0.).closed_length;
    const double fine   = run_two_blocks(16, JointLawKind::rigid, 0.).closed_length;
    std::cout << "closed length (m) at h = 1/4, 1/8, 1/16: " << coarse << " "
              << medium << " " << fine << std::endl;
    // Successive differences must shrink, and the last one be within two
    // fine cells (the nodal closed length resolves the tip to a cell).
    EXPECT_LT(std::abs(fine - medium), std::abs(medium - coarse) + 1e-12);
    EXPECT_LT(std::abs(fine - medium), 2. * block_width / 16.);
  }

  TEST(TwoBlocks, StiffCompliantLawApproachesRigidLaw)
  {
    const TwoBlockOutcome rigid = run_two_blocks(8, JointLawKind::rigid, 0.);
    const TwoBlockOutcome stiff =
      run_two_blocks(8, JointLawKind::compliant, 1e14);
    std::cout << "rigid vs compliant(1e14): rotation " << rigid.right_rotation
              << " " << stiff.right_rotation << ", averaged peak "
              << rigid.averaged_peak << " " << stiff.averaged_peak
              << ", closed length " << rigid.closed_length << " "
              << stiff.closed_length << std::endl;
    // The acceptance bound: within 1 %.
    EXPECT_NEAR(stiff.right_rotation, rigid.right_rotation,
                0.01 * std::abs(rigid.right_rotation));
    EXPECT_NEAR(stiff.averaged_peak, rigid.averaged_peak,
                0.01 * rigid.averaged_peak);
    EXPECT_NEAR(stiff.joint_normal_force, rigid.joint_normal_force,
                1e-8 * applied_lateral_force);
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
