// Load stepping: n increments of 1/n reach the end of a stage in exactly n
// increments. Ten steps of 0.1 sum to 0.9999999999999999 in floating
// point; that remainder must not become an eleventh, zero-length increment
// (on refined meshes it made the default scene cycle in its last uplift
// increment: every slipping pair is re-tested exactly on its Coulomb limit).
#include "block_mesh.h"
#include "test_scenes.h"

#include <contact/contact_solver.h>
#include <contact/uplift.h>

#include <gtest/gtest.h>

#include <deal.II/grid/tria.h>

namespace
{
  using namespace FloorBlock;
  using namespace FloorBlock::Contact;

  constexpr dealii::types::boundary_id block_sides = 10, block_bottom = 11,
                                       block_top = 12;
  constexpr dealii::types::boundary_id base_sides = 20, base_top = 21,
                                       base_bottom = 22;

  TEST(LoadSteps, TenUpliftStepsAreTenIncrements)
  {
    dealii::Triangulation<2> mesh;
    Testing::make_block_assembly(
      {{0., 1., 0., 0.5, 4, 2, 1, block_sides, block_sides, block_bottom, block_top},
       {0., 1., -0.5, 0., 4, 2, 2, base_sides, base_sides, base_bottom, base_top}},
      mesh);
    SceneDefinition<2> scene;
    scene.model.laws.emplace(1, Testing::table_rock());
    scene.model.laws.emplace(2, Testing::table_rock());
    scene.model.densities[1] = 2500.; // kg/m^3
    scene.model.gravity[1]   = -9.81; // m/s^2
    SupportDefinition<2> base = Testing::fixed_support(base_bottom, true, true);
    base.moves_with_uplift    = true;
    scene.supports            = {base};
    JointDefinition<2> joint;
    joint.name                        = "bedding";
    joint.side_a                      = base_top;
    joint.side_b                      = block_bottom;
    joint.parameters.normal_stiffness = 9e9;
    joint.parameters.shear_stiffness  = 6.7e9;
    joint.parameters.friction_angle   = 30. * M_PI / 180.;
    scene.joints                      = {joint};
    scene.uplift.mode                 = UpliftMode::vertical_translation;
    scene.uplift.magnitude            = 1e-3; // m
    constexpr unsigned int n_uplift   = 10;
    scene.steps                       = {1, 0, n_uplift};

    ContactSolver     solver(mesh, scene, Testing::test_settings());
    const SolveResult result = solver.run();
    ASSERT_EQ(result.increments.size(), 1u + n_uplift);
    for (unsigned int k = 1; k <= n_uplift; ++k)
      {
        EXPECT_EQ(result.increments[k].stage, LoadStage::uplift);
        // Summed steps: round-off of a few ulps, exactly 1 at the end.
        EXPECT_NEAR(result.increments[k].stage_factor,
                    static_cast<double>(k) / n_uplift, 1e-15);
      }
    EXPECT_EQ(result.increments.back().stage_factor, 1.);
  }
} // namespace
