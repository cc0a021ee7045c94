// Block on an incline with Coulomb friction: it stays iff tan(alpha) < mu,
// and a stuck block's joint carries exactly W sin(alpha).
#include "block_mesh.h"
#include "test_scenes.h"

#include <contact/contact_solver.h>

#include <gtest/gtest.h>

#include <deal.II/grid/tria.h>

#include <cmath>

namespace
{
  using namespace FloorBlock;
  using namespace FloorBlock::Contact;

  constexpr dealii::types::boundary_id block_sides = 10, block_bottom = 11,
                                       block_top = 12;
  constexpr dealii::types::boundary_id base_sides = 20, base_top = 21,
                                       base_bottom = 22;
  constexpr double density              = 2500.; // kg/m^3
  constexpr double gravity_acceleration = 9.81;  // m/s^2
  constexpr double block_width = 1., block_height = 0.5; // m
  const double     friction_angle = 30. * M_PI / 180.;

  /**
   * Tilting the gravity vector by alpha is the same problem as tilting the
   * geometry, without a rotated mesh.
   */
  SceneDefinition<2>
  incline_scene(const double incline)
  {
    SceneDefinition<2> scene;
    scene.model.laws.emplace(1, Testing::table_rock());
    scene.model.laws.emplace(2, Testing::table_rock());
    scene.model.densities[1] = density;
    scene.model.gravity[0]   = gravity_acceleration * std::sin(incline);
    scene.model.gravity[1]   = -gravity_acceleration * std::cos(incline);
    scene.supports = {Testing::fixed_support(base_bottom, true, true)};
    JointDefinition<2> joint;
    joint.name                        = "bedding";
    joint.side_a                      = base_top;
    joint.side_b                      = block_bottom;
    joint.law                         = JointLawKind::compliant;
    joint.parameters.normal_stiffness = 9e9; // Table 6.1
    joint.parameters.shear_stiffness  = 6.7e9;
    joint.parameters.friction_angle   = friction_angle;
    scene.joints                      = {joint};
    scene.steps                       = {1, 0, 0};
    return scene;
  }

  void
  make_mesh(dealii::Triangulation<2> &mesh)
  {
    Testing::make_block_assembly(
      {{0., block_width, 0., block_height, 8, 4, 1, block_sides, block_sides, block_bottom, block_top},
       {0., block_width, -0.5, 0., 8, 4, 2, base_sides, base_sides, base_bottom, base_top}},
      mesh);
  }

  TEST(Incline, StuckBelowFrictionAngle)
  {
    const double incline = std::atan(0.9 * std::tan(friction_angle));
    dealii::Triangulation<2> mesh;
    make_mesh(mesh);
    ContactSolver     solver(mesh, incline_scene(incline), Testing::test_settings());
    const SolveResult result = solver.run();
    const IncrementResult &last   = result.increments.back();
    const JointReport     &joint  = last.joints.at(0);
    const double weight = density * gravity_acceleration * block_width * block_height;
    // Equilibrium of the block alone; Newton tolerance 1e-12, so 1e-8.
    // Side A is the base, tangent (-n_y, n_x) = (-1, 0): the base holds the
    // block back against +x, so the shear traction on the joint is
    // +W sin(alpha) along -x.
    EXPECT_NEAR(std::abs(joint.shear_force), weight * std::sin(incline), 1e-8 * weight);
    EXPECT_NEAR(joint.normal_force, weight * std::cos(incline), 1e-8 * weight);
    // Elastic bodies slip locally at the joint ends (Cattaneo-Mindlin
    // partial slip) even below the limit; the block as a whole sticks.
    EXPECT_GT(joint.counts.n_stick, 0u);
    std::cout << "stick/slip/open " << joint.counts.n_stick << "/"
              << joint.counts.n_slip << "/" << joint.counts.n_open << std::endl;
    EXPECT_LT(last.balance.relative_imbalance, 1e-8);
  }

  TEST(Incline, NoEquilibriumAboveFrictionAngle)
  {
    // Quasi-statics has no equilibrium for a sliding block: the solver must
    // fail with every closed pair at the slip limit in its last iterate.
    const double incline = std::atan(1.1 * std::tan(friction_angle));
    dealii::Triangulation<2> mesh;
    make_mesh(mesh);
    ContactSolver solver(mesh, incline_scene(incline), Testing::test_settings());
    try
      {
        solver.run();
        FAIL() << "a block above the friction angle found an equilibrium";
      }
    catch (const ContactSolveFailure &failure)
      {
        EXPECT_GT(failure.last_iterate_counts.n_closed(), 0u);
        EXPECT_EQ(failure.last_iterate_counts.n_stick, 0u);
        EXPECT_FALSE(failure.attempts.empty());
        EXPECT_FALSE(failure.last_converged.has_value());
      }
  }
} // namespace
