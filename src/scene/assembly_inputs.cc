#include <scene/assembly_inputs.h>

namespace FloorBlock::Scene
{
  Geometry::AssemblyDescription
  assembly_description(const Parameters::ScenarioParameters &scene)
  {
    Geometry::AssemblyDescription description;
    description.n_blocks               = scene.geometry.n_blocks;
    description.block_width            = scene.geometry.block_width;
    description.block_height           = scene.geometry.block_height;
    description.face_block_width       = scene.geometry.face_block_width;
    description.base_thickness         = scene.geometry.base_thickness;
    description.rigid_base             = scene.bedding.rigid_base;
    description.bedding_shape          = scene.bedding.shape;
    description.inclination            = scene.bedding.inclination;
    description.curvature              = scene.bedding.curvature;
    description.floor_uplift           = scene.bedding.floor_uplift;
    description.corner_rounding_radius = scene.geometry.corner_rounding_radius;
    description.mesh_corner_size       = scene.mesh.corner_size;
    description.mesh_far_size          = scene.mesh.far_size;
    description.mesh_growth_rate       = scene.mesh.growth_rate;
    description.matching_joints        = scene.mesh.matching_joints;
    return description;
  }
} // namespace FloorBlock::Scene
