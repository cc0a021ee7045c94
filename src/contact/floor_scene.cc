#include <common/input_error.h>
#include <contact/floor_scene.h>
#include <geometry/ids.h>

#include <string>

namespace FloorBlock
{
  namespace Contact
  {
    namespace Ids = Geometry::Ids;

    SceneDefinition<2>
    make_floor_scene(const FloorSceneSettings &settings)
    {
      if (settings.n_blocks < 1 || settings.n_blocks > Ids::max_n_blocks)
        throw InputError("Geometry/Number of blocks",
                         std::to_string(settings.n_blocks),
                         "1 .. " + std::to_string(Ids::max_n_blocks));
      SceneDefinition<2> scene;
      for (unsigned int i = 1; i <= settings.n_blocks; ++i)
        {
          scene.model.laws.emplace(Ids::block_material(i), settings.rock);
          scene.model.densities[Ids::block_material(i)] = settings.density;
        }
      scene.model.laws.emplace(Ids::face_block_material, settings.rock);
      scene.model.densities[Ids::face_block_material] = settings.density;
      scene.model.laws.emplace(Ids::base_material, settings.rock);
      scene.model.gravity[1] = -settings.gravity;
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

      for (unsigned int j = 1; j <= settings.n_blocks; ++j)
        {
          JointDefinition<2> vertical;
          vertical.name       = "vertical " + std::to_string(j);
          vertical.side_a     = Ids::vertical_joint_face_side(j);
          vertical.side_b     = Ids::vertical_joint_free_side(j);
          vertical.law        = settings.law;
          vertical.parameters = settings.vertical_joints;
          scene.joints.push_back(vertical);
        }
      for (unsigned int i = 1; i <= settings.n_blocks; ++i)
        {
          JointDefinition<2> bedding;
          bedding.name       = "bedding " + std::to_string(i);
          bedding.side_a     = Ids::bedding_base_side(i);
          bedding.side_b     = Ids::bedding_block_side(i);
          bedding.law        = settings.law;
          bedding.parameters = settings.bedding_joints;
          scene.joints.push_back(bedding);
        }

      SupportDefinition<2> face_outer;
      face_outer.boundary_id            = Ids::face_block_outer_side;
      face_outer.constrained_components = {{true, true}};
      SupportDefinition<2> face_bottom  = face_outer;
      face_bottom.boundary_id = Ids::bedding_block_side(Ids::face_block_index);
      SupportDefinition<2> base         = face_outer;
      base.boundary_id                  = Ids::base_bottom;
      base.moves_with_uplift            = true;
      scene.supports = {face_outer, face_bottom, base};
      scene.uplift   = settings.uplift;
      scene.steps    = settings.steps;
      return scene;
    }
  } // namespace Contact
} // namespace FloorBlock
