#include <contact/contact_solver.h>
#include <verification/block_assembly_mesh.h>
#include <verification/incline_verification.h>
#include <verification/verification_setup.h>

#include <deal.II/grid/tria.h>

#include <postprocess/increment_post_processor.h>

#include <cmath>

namespace FloorBlock::Verification
{
  // The model's ids and sizes: a named namespace, as the verification models
  // share names (block, base, ...) within one unity batch.
  namespace InclineModel
  {
    constexpr dealii::types::boundary_id block_sides = 10, block_bottom = 11,
                                         block_top  = 12;
    constexpr dealii::types::boundary_id base_sides = 20, base_top = 21,
                                         base_bottom = 22;
    constexpr dealii::types::material_id block = 1, base = 2;
    constexpr double                     density              = 2500.; // kg/m^3
    constexpr double                     gravity_acceleration = 9.81;  // m/s^2
    constexpr double block_width = 1., block_height = 0.5;             // m
    constexpr double base_depth = 0.5;                                 // m

    Contact::ContactProblem<2>
    incline_scene(const InclineSettings &settings)
    {
      Contact::ContactProblem<2> scene;
      scene.model.laws.emplace(block, table_rock());
      scene.model.laws.emplace(base, table_rock());
      scene.model.densities[block] = density;
      scene.model.gravity[0] =
        gravity_acceleration * std::sin(settings.incline);
      scene.model.gravity[1] =
        -gravity_acceleration * std::cos(settings.incline);
      scene.supports = {fixed_support(base_bottom, true, true)};
      Contact::JointDefinition<2> joint;
      joint.name                        = "bedding";
      joint.side_a                      = base_top;
      joint.side_b                      = block_bottom;
      joint.law                         = settings.law;
      joint.parameters.normal_stiffness = settings.normal_stiffness;
      joint.parameters.shear_stiffness  = settings.shear_stiffness;
      joint.parameters.friction_angle   = settings.friction_angle;
      scene.joints                      = {joint};
      scene.steps                       = {1, 0, 0};
      return scene;
    }
  } // namespace InclineModel

  InclineResult
  run_incline_verification(const InclineSettings &settings)
  {
    using namespace InclineModel;
    dealii::Triangulation<2> mesh;
    make_block_assembly({{0.,
                          block_width,
                          0.,
                          block_height,
                          8,
                          4,
                          block,
                          block_sides,
                          block_sides,
                          block_bottom,
                          block_top},
                         {0.,
                          block_width,
                          -base_depth,
                          0.,
                          8,
                          4,
                          base,
                          base_sides,
                          base_sides,
                          base_bottom,
                          base_top}},
                        mesh);
    InclineResult result;
    result.weight = density * gravity_acceleration * block_width * block_height;
    const Contact::ContactSolverSettings numerics = verification_settings();
    Contact::ContactSolver<2> solver(mesh, incline_scene(settings), numerics);
    try
      {
        result.stuck =
          Postprocess::solve_with_reports(solver, numerics).increments.back();
      }
    catch (const Contact::ContactSolveFailure &failure)
      {
        result.slipped             = true;
        result.last_iterate_counts = failure.last_iterate_counts;
        result.n_failed_attempts   = failure.attempts.size();
        result.had_converged_state = failure.last_converged.has_value();
      }
    return result;
  }

  bool
  slips(const InclineResult &result)
  {
    return result.slipped && result.last_iterate_counts.n_stick == 0 &&
           result.last_iterate_counts.n_closed() > 0 &&
           !result.had_converged_state;
  }
} // namespace FloorBlock::Verification
