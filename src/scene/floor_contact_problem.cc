#include <common/input_error.h>
#include <geometry/ids.h>
#include <scene/floor_contact_problem.h>

#include <cmath>
#include <string>

namespace FloorBlock::Scene
{
  namespace Ids = Geometry::Ids;

  Contact::ContactProblem<2>
  make_floor_contact_problem(const FloorProblemSettings &settings)
  {
    if (settings.n_blocks < 1 || settings.n_blocks > Ids::max_n_blocks)
      throw InputError("Geometry/Number of blocks",
                       std::to_string(settings.n_blocks),
                       "1 .. " + std::to_string(Ids::max_n_blocks));
    Contact::ContactProblem<2> scene;
    for (unsigned int i = 1; i <= settings.n_blocks; ++i)
      {
        scene.model.laws.emplace(Ids::block_material(i), settings.rock);
        scene.model.densities[Ids::block_material(i)] = settings.density;
      }
    scene.model.laws.emplace(Ids::face_block_material, settings.rock);
    scene.model.densities[Ids::face_block_material] = settings.density;
    if (!settings.rigid_base)
      scene.model.laws.emplace(Ids::base_material, settings.rock);
    scene.model.down[0] = std::sin(settings.frame_dip);
    scene.model.down[1] = -std::cos(settings.frame_dip);
    scene.model.gravity = settings.gravity * scene.model.down;
    for (const auto &[block, pressure] : settings.support_pressures)
      {
        if (block < 1 || block > settings.n_blocks)
          throw InputError("Loads/Support pressure block",
                           std::to_string(block),
                           "1 .. number of blocks");
        scene.model.pressures[Ids::floor_surface(block)] = pressure;
        if (settings.vertical_support_load)
          scene.model.vertical_pressures.insert(Ids::floor_surface(block));
      }

    const auto add_joint = [&](const std::string               &name,
                               const dealii::types::boundary_id side_a,
                               const dealii::types::boundary_id side_b,
                               const Contact::JointConstants   &parameters) {
      Contact::JointDefinition<2> joint;
      joint.name       = name;
      joint.side_a     = side_a;
      joint.side_b     = side_b;
      joint.law        = settings.law;
      joint.parameters = parameters;
      scene.joints.push_back(joint);
    };
    for (unsigned int j = 1; j <= settings.n_blocks; ++j)
      add_joint(vertical_joint_name(j),
                Ids::vertical_joint_face_side(j),
                Ids::vertical_joint_free_side(j),
                settings.vertical_joints);
    for (unsigned int i = 1; i <= settings.n_blocks; ++i)
      if (settings.rigid_base)
        {
          // Side A is the block bottom; the plane lies below it.
          add_joint("bedding " + std::to_string(i),
                    Ids::bedding_block_side(i),
                    Ids::bedding_block_side(i),
                    settings.bedding_joints);
          Contact::JointDefinition<2> &joint = scene.joints.back();
          joint.against_rigid_plane          = true;
          joint.plane_point                  = dealii::Point<2>();
          joint.plane_normal                 = dealii::Tensor<1, 2>({0., -1.});
          joint.plane_moves_with_uplift      = true;
        }
      else
        add_joint("bedding " + std::to_string(i),
                  Ids::bedding_base_side(i),
                  Ids::bedding_block_side(i),
                  settings.bedding_joints);

    Contact::SupportDefinition<2> face_outer;
    face_outer.boundary_id                    = Ids::face_block_outer_side;
    face_outer.constrained_components         = {{true, true}};
    Contact::SupportDefinition<2> face_bottom = face_outer;
    face_bottom.boundary_id = Ids::bedding_block_side(Ids::face_block_index);
    Contact::SupportDefinition<2> base = face_outer;
    base.boundary_id                   = Ids::base_bottom;
    base.moves_with_uplift             = true;
    scene.supports                     = {face_outer, face_bottom};
    if (!settings.rigid_base)
      scene.supports.push_back(base);
    scene.uplift = settings.uplift;
    scene.steps  = settings.steps;
    return scene;
  }

  std::string
  vertical_joint_name(const unsigned int j)
  {
    return "vertical " + std::to_string(j);
  }

  bool
  is_vertical_joint(const std::string &name)
  {
    return name.rfind("vertical ", 0) == 0;
  }
} // namespace FloorBlock::Scene
