#include <common/units.h>
#include <contact/contact_solver.h>
#include <verification/block_assembly_mesh.h>
#include <verification/two_blocks_verification.h>
#include <verification/verification_setup.h>

#include <deal.II/grid/tria.h>

#include <postprocess/increment_post_processor.h>

#include <cmath>

namespace FloorBlock::Verification
{
  // The model's ids and sizes: a named namespace, as the verification models
  // share names (block, base, ...) within one unity batch.
  namespace TwoBlocksModel
  {
    // Left block (fixed, like the face block), right block, base under it.
    constexpr dealii::types::boundary_id left_outer = 11, left_joint = 12,
                                         left_bottom = 13, left_top = 14;
    constexpr dealii::types::boundary_id right_joint = 21, right_outer = 22,
                                         right_bottom = 23, right_top = 24,
                                         right_outer_upper = 25;
    constexpr dealii::types::boundary_id base_sides = 31, base_top = 32,
                                         base_bottom = 33;
    constexpr dealii::types::material_id left_block = 1, right_block = 2,
                                         base = 3;
    constexpr double block_height             = 2.;  // m
    constexpr double block_width              = 1.;  // m
    constexpr double base_depth               = 0.5; // m
    constexpr double loaded_from_y =
      1.5; // m, lateral load on the upper quarter
    constexpr double density                 = 2500.; // kg/m^3
    constexpr double gravity_acceleration    = 9.81;  // m/s^2
    constexpr double vertical_friction_angle = Units::degrees_to_radians(30.);
  } // namespace TwoBlocksModel

  TwoBlocksResult
  run_two_blocks_verification(const TwoBlocksSettings &settings)
  {
    using namespace TwoBlocksModel;
    const unsigned int       n_x = settings.cells_per_metre;
    const unsigned int       n_y = 2 * settings.cells_per_metre;
    dealii::Triangulation<2> mesh;
    make_block_assembly({{-block_width,
                          0.,
                          0.,
                          block_height,
                          n_x,
                          n_y,
                          left_block,
                          left_outer,
                          left_joint,
                          left_bottom,
                          left_top},
                         {0.,
                          block_width,
                          0.,
                          block_height,
                          n_x,
                          n_y,
                          right_block,
                          right_joint,
                          right_outer,
                          right_bottom,
                          right_top,
                          loaded_from_y,
                          right_outer_upper},
                         {0.,
                          block_width,
                          -base_depth,
                          0.,
                          n_x,
                          n_x / 2,
                          base,
                          base_sides,
                          base_sides,
                          base_bottom,
                          base_top}},
                        mesh);
    // The blocks mirror each other about the joint x = 0, so flagging by
    // distance to the corner refines both sides of the joint alike: the
    // new joint nodes, hanging ones included, keep their partners.
    const dealii::Point<2> joint_top(0., block_height);
    for (unsigned int level = 0; level < settings.corner_refinements; ++level)
      {
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->material_id() != base &&
              cell->center().distance(joint_top) <
                settings.corner_refinement_radius)
            cell->set_refine_flag();
        mesh.execute_coarsening_and_refinement();
      }
    Contact::ContactProblem<2> scene;
    for (const dealii::types::material_id body :
         {left_block, right_block, base})
      scene.model.laws.emplace(body, table_rock());
    scene.model.densities[right_block]       = density;
    scene.model.gravity[1]                   = -gravity_acceleration;
    scene.model.pressures[right_outer_upper] = settings.lateral_pressure;
    scene.supports = {fixed_support(left_outer, true, true),
                      fixed_support(left_bottom, true, true),
                      fixed_support(base_bottom, true, true)};
    Contact::JointDefinition<2> vertical;
    vertical.name                        = "vertical";
    vertical.side_a                      = left_joint;
    vertical.side_b                      = right_joint;
    vertical.law                         = settings.law;
    vertical.parameters.normal_stiffness = settings.joint_stiffness;
    vertical.parameters.shear_stiffness  = settings.joint_stiffness;
    vertical.parameters.friction_angle   = vertical_friction_angle;
    Contact::JointDefinition<2> bedding  = vertical;
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
    scene.steps                                   = {0, 2, 0};
    const Contact::ContactSolverSettings numerics = verification_settings();
    Contact::ContactSolver<2>            solver(mesh, scene, numerics);
    const Contact::SolveResult           solved =
      Postprocess::solve_with_reports(solver, numerics);
    const Contact::IncrementResult &last = solved.increments.back();
    TwoBlocksResult                 result;
    result.applied_lateral_force =
      settings.lateral_pressure * (block_height - loaded_from_y);
    result.joint_normal_force = last.joints.at(0).normal_force;
    result.closed_length      = last.joints.at(0).closed_length;
    result.averaged_peak      = last.joints.at(0).averaged_peak_normal_stress;
    result.right_rotation     = last.motions.at(right_block).rotation;
    result.relative_imbalance = last.balance.relative_imbalance;
    result.block_height       = block_height;
    return result;
  }
} // namespace FloorBlock::Verification
