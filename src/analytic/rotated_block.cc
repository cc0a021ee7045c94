#include <analytic/rotated_block.h>

#include <cmath>

namespace FloorBlock::Analytic
{
  namespace Internal
  {
    FrameForce
    force_from_away_neighbour(const BlockChain &chain,
                              const std::size_t block,
                              const double      lateral_force,
                              const double      joint_shear)
    {
      const double relative_rotation =
        chain.inclination[block - 1] - chain.inclination[block];
      const double cos_delta = std::cos(relative_rotation);
      const double sin_delta = std::sin(relative_rotation);
      FrameForce   force;
      force.along  = -(lateral_force * cos_delta + joint_shear * sin_delta);
      force.normal = joint_shear * cos_delta - lateral_force * sin_delta;
      return force;
    }

    double
    load_moment_about_top_corner(const BlockChain &chain,
                                 const std::size_t block)
    {
      const double alpha  = chain.inclination[block];
      const double width  = chain.block_width;
      const double height = chain.block_height;
      // The weight acts at the block centre, whose position relative to
      // the top corner has a down-slope part; the support load acts on the
      // top edge, at (1 - r) L from the face-side edge.
      const double weight_arm =
        (width * std::cos(alpha) + height * std::sin(alpha)) / 2.;
      const double support_arm =
        (1. - chain.support_load_position) * width * std::cos(alpha);
      return chain.weight[block] * weight_arm +
             chain.support_load[block] * support_arm;
    }
  } // namespace Internal
} // namespace FloorBlock::Analytic
