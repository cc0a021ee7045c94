#include <analytic/chain_checks.h>
#include <analytic/rotated_block.h>
#include <analytic/rotation_no_vertical_slip.h>

#include <cmath>

namespace FloorBlock::Analytic
{
  namespace
  {
    /** First block whose joint shear exceeds its friction, 0 if none. */
    std::size_t
    first_block_exceeding_friction(const ChainForces &forces,
                                   const double       tan_vertical)
    {
      for (std::size_t block = 0; block < forces.joint_shear.size(); ++block)
        if (std::abs(forces.joint_shear[block]) >
            forces.lateral_force[block] * tan_vertical)
          return block + 1;
      return 0;
    }
  } // namespace

  ChainForces
  rotation_no_vertical_slip(const BlockChain &chain)
  {
    if (validate(chain) != Status::ok)
      return Internal::no_finite_answer(Status::invalid_input, 0);

    const double tan_bedding = std::tan(chain.bedding_friction);
    // Lever of N_i minus lever of the base friction about the top corner.
    const double rotation_denominator =
      chain.block_width - chain.block_height * tan_bedding;
    if (rotation_denominator <=
        Internal::singular_denominator * chain.block_width)
      return Internal::no_finite_answer(
        Status::rotation_denominator_nonpositive, 1);

    ChainForces forces;
    for (std::size_t block = 0; block < chain.n_blocks(); ++block)
      {
        Internal::FrameForce incoming; // block 1 has a free away side
        if (block > 0)
          incoming =
            Internal::force_from_away_neighbour(chain,
                                                block,
                                                forces.lateral_force[block - 1],
                                                forces.joint_shear[block - 1]);
        const double alpha = chain.inclination[block];
        const double vertical_load =
          chain.weight[block] + chain.support_load[block];

        const double normal_force =
          (Internal::load_moment_about_top_corner(chain, block) -
           chain.block_width * incoming.normal) /
          rotation_denominator;
        forces.normal_force.push_back(normal_force);
        forces.lateral_force.push_back(-incoming.along +
                                       normal_force * tan_bedding +
                                       vertical_load * std::sin(alpha));
        forces.joint_shear.push_back(normal_force + incoming.normal -
                                     vertical_load * std::cos(alpha));
        forces.normal_force_offset.push_back(0.);
      }
    if (!Internal::all_finite(forces))
      return Internal::no_finite_answer(
        Status::rotation_denominator_nonpositive, 0);
    Internal::check_no_tension(forces);
    if (forces.status != Status::ok)
      return forces;
    const std::size_t slipping_block =
      first_block_exceeding_friction(forces, std::tan(chain.vertical_friction));
    if (slipping_block != 0)
      {
        forces.status        = Status::vertical_friction_exceeded;
        forces.failing_block = slipping_block;
      }
    return forces;
  }
} // namespace FloorBlock::Analytic
