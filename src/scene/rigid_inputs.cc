#include <scene/analytic_inputs.h>
#include <scene/assembly_inputs.h>
#include <scene/contact_inputs.h>
#include <scene/rigid_inputs.h>

namespace FloorBlock::Scene
{
  RigidBlocks::ModelDescription
  rigid_model_description(const Parameters::ScenarioParameters &scene)
  {
    const FloorProblemSettings    floor = floor_problem_settings(scene);
    RigidBlocks::ModelDescription description;
    description.assembly           = assembly_description(scene);
    description.density            = floor.density;
    description.gravity            = floor.gravity;
    description.support_line_loads = block_chain(scene).support_load;
    // A uniform pressure on the block top has its resultant at the centre.
    description.support_load_position = 0.5;
    description.bedding_joint         = floor.bedding_joints;
    description.vertical_joint        = floor.vertical_joints;
    description.uplift                = floor.uplift;
    description.steps                 = floor.steps;

    RigidBlocks::RigidSolverSettings &solver = description.solver;
    solver.n_points_per_joint          = scene.model.rigid_points_per_joint;
    solver.newton.relative_tolerance   = scene.solver.newton_tolerance;
    solver.newton.max_iterations       = scene.solver.max_newton_iterations;
    solver.max_cutbacks                = scene.solver.max_cutbacks;
    solver.profiles_of_every_increment = true;
    return description;
  }

  bool
  uses_rigid_blocks(const Parameters::ScenarioParameters &scene)
  {
    return scene.model.chosen == Parameters::BlockModel::rigid;
  }
} // namespace FloorBlock::Scene
