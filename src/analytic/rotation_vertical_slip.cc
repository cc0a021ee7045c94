#include <analytic/chain_checks.h>
#include <analytic/rotated_block.h>
#include <analytic/rotation_vertical_slip.h>

#include <cmath>

namespace FloorBlock::Analytic
{
  namespace
  {
    /** First block whose base force lies off its base, 0 if none. */
    std::size_t
    first_block_off_base(const ChainForces &forces, const double width)
    {
      for (std::size_t block = 0; block < forces.normal_force_offset.size();
           ++block)
        {
          const double offset = forces.normal_force_offset[block];
          if (offset < 0. || offset > width)
            return block + 1;
        }
      return 0;
    }
  } // namespace

  ChainForces
  rotation_vertical_slip(const BlockChain &chain)
  {
    if (validate(chain) != Status::ok)
      return Internal::no_finite_answer(Status::invalid_input, 0);

    const double tan_bedding  = std::tan(chain.bedding_friction);
    const double tan_vertical = std::tan(chain.vertical_friction);
    const double locking      = 1. - tan_bedding * tan_vertical; // 6.41
    if (locking <= Internal::singular_denominator)
      return Internal::no_finite_answer(Status::self_locking, 1);

    const double width  = chain.block_width;
    const double height = chain.block_height;
    ChainForces  forces;
    for (std::size_t block = 0; block < chain.n_blocks(); ++block)
      {
        Internal::FrameForce incoming;
        if (block > 0)
          incoming =
            Internal::force_from_away_neighbour(chain,
                                                block,
                                                forces.lateral_force[block - 1],
                                                forces.joint_shear[block - 1]);
        const double alpha = chain.inclination[block];
        const double vertical_load =
          chain.weight[block] + chain.support_load[block];

        const double lateral_force =
          (-incoming.along - tan_bedding * incoming.normal +
           vertical_load * (std::sin(alpha) + tan_bedding * std::cos(alpha))) /
          locking;
        const double normal_force = vertical_load * std::cos(alpha) +
                                    lateral_force * tan_vertical -
                                    incoming.normal;
        // Moment about the face-side top corner fixes the lever of N_i
        // from the face-side edge; report it from the uphill corner.
        const double lever_from_face_side =
          normal_force > 0. ?
            (Internal::load_moment_about_top_corner(chain, block) +
             height * tan_bedding * normal_force - width * incoming.normal) /
              normal_force :
            0.;
        forces.lateral_force.push_back(lateral_force);
        forces.normal_force.push_back(normal_force);
        forces.joint_shear.push_back(lateral_force * tan_vertical);
        forces.normal_force_offset.push_back(width - lever_from_face_side);
      }
    if (!Internal::all_finite(forces))
      return Internal::no_finite_answer(Status::self_locking, 0);
    Internal::check_no_tension(forces);
    if (forces.status != Status::ok)
      return forces;
    const std::size_t tipping_block = first_block_off_base(forces, width);
    if (tipping_block != 0)
      {
        forces.status        = Status::normal_force_outside_base;
        forces.failing_block = tipping_block;
      }
    return forces;
  }
} // namespace FloorBlock::Analytic
