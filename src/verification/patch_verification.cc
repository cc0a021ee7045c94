#include <contact/contact_solver.h>
#include <verification/block_assembly_mesh.h>
#include <verification/patch_verification.h>
#include <verification/verification_setup.h>

#include <deal.II/grid/tria.h>

#include <postprocess/increment_post_processor.h>

namespace FloorBlock::Verification
{
  namespace
  {
    // Bodies 1 (lower) and 2 (upper), each a unit square.
    constexpr dealii::types::boundary_id lower_left = 11, lower_right = 12,
                                         lower_bottom = 13, lower_top = 14;
    constexpr dealii::types::boundary_id upper_left = 21, upper_right = 22,
                                         upper_bottom = 23, upper_top = 24;
    constexpr double joint_length = 1.; // m
    /** Joint springs (Pa/m): stiff, yet the compliant law stays well posed. */
    constexpr double joint_stiffness = 1e12;
    /** rad; irrelevant for the answer (zero shear), but finite. */
    constexpr double joint_friction_angle = 0.5;
  } // namespace

  PatchResult
  run_patch_verification(const PatchSettings &settings)
  {
    dealii::Triangulation<2> mesh;
    // Different cell counts across the joint in y, matching in x.
    make_block_assembly({{0.,
                          joint_length,
                          0.,
                          1.,
                          4,
                          3,
                          1,
                          lower_left,
                          lower_right,
                          lower_bottom,
                          lower_top},
                         {0.,
                          joint_length,
                          1.,
                          2.,
                          4,
                          5,
                          2,
                          upper_left,
                          upper_right,
                          upper_bottom,
                          upper_top}},
                        mesh);
    Contact::ContactProblem<2> scene;
    scene.model.laws.emplace(1, table_rock());
    scene.model.laws.emplace(2, table_rock());
    scene.model.pressures[upper_top] = settings.pressure;
    // Rollers: uniform uniaxial stress is then the exact solution, and
    // both bodies expand laterally alike, so the joint shear is zero.
    scene.supports = {fixed_support(lower_bottom, false, true),
                      fixed_support(lower_left, true, false),
                      fixed_support(upper_left, true, false)};
    Contact::JointDefinition<2> joint;
    joint.name                        = "patch";
    joint.side_a                      = lower_top;
    joint.side_b                      = upper_bottom;
    joint.law                         = settings.law;
    joint.parameters.normal_stiffness = joint_stiffness;
    joint.parameters.shear_stiffness  = joint_stiffness;
    joint.parameters.friction_angle   = joint_friction_angle;
    scene.joints                      = {joint};
    scene.steps                       = {0, 1, 0};
    Contact::ContactSolverSettings numerics =
      verification_settings(settings.fe_degree);
    numerics.linear.kind = settings.linear_solver;
    Contact::ContactSolver<2>  solver(mesh, scene, numerics);
    const Contact::SolveResult solved =
      Postprocess::solve_with_reports(solver, numerics);
    PatchResult result;
    result.increment        = solved.increments.back();
    result.n_increments     = solved.increments.size();
    result.joint_length     = joint_length;
    result.applied_pressure = settings.pressure;
    return result;
  }
} // namespace FloorBlock::Verification
