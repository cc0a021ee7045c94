#include <geometry/bedding_profile.h>
#include <rigid/block_loads.h>
#include <rigid/joint_layout.h>

namespace FloorBlock::RigidBlocks
{
  std::vector<BlockLoads>
  block_loads(const ModelDescription &description)
  {
    const Geometry::AssemblyDescription &assembly = description.assembly;
    const Geometry::BeddingProfile       profile =
      Geometry::BeddingProfile::geometry_profile(assembly);
    // A block between y_b(x) and y_b(x) + H has area L H whatever y_b.
    const double weight = description.density * description.gravity *
                          assembly.block_width * assembly.block_height;
    std::vector<BlockLoads> loads(assembly.n_blocks);
    for (unsigned int index = 0; index < assembly.n_blocks; ++index)
      {
        BlockLoads &block = loads[index];
        block.weight      = weight;
        block.centroid    = block_centroid(assembly, index);
        if (!description.support_line_loads.empty())
          block.support_load = description.support_line_loads[index];
        const double side_away_from_face =
          (assembly.n_blocks - index) * assembly.block_width;
        const double x_load =
          side_away_from_face -
          description.support_load_position * assembly.block_width;
        block.support_point =
          dealii::Point<2>(x_load,
                           profile.height(x_load) + assembly.block_height);
      }
    return loads;
  }

  std::array<double, 3>
  applied_force(const BlockLoads &loads,
                const double      gravity_factor,
                const double      support_factor)
  {
    const double support = support_factor * loads.support_load;
    const double lever   = loads.support_point[0] - loads.centroid[0];
    // Both loads point down (-y); the weight acts at the centroid.
    return {{0., -gravity_factor * loads.weight - support, -lever * support}};
  }
} // namespace FloorBlock::RigidBlocks
