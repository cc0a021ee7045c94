#include <analytic/chain_checks.h>
#include <analytic/slip_no_rotation.h>

#include <cmath>

namespace FloorBlock::Analytic
{
  ChainForces
  slip_no_rotation(const BlockChain &chain)
  {
    if (validate(chain) != Status::ok)
      return Internal::no_finite_answer(Status::invalid_input, 0);

    const std::size_t n_blocks     = chain.n_blocks();
    const double      tan_bedding  = std::tan(chain.bedding_friction);
    const double      tan_vertical = std::tan(chain.vertical_friction);

    ChainForces forces;
    double      previous_lateral_force = 0.; // Q_0: block 1 has a free side
    for (std::size_t block = 0; block < n_blocks; ++block)
      {
        const double sin_alpha = std::sin(chain.inclination[block]);
        const double cos_alpha = std::cos(chain.inclination[block]);
        const double vertical_load =
          chain.weight[block] + chain.support_load[block];
        // a: horizontal thrust per unit base normal force (6.4);
        // c: bed-normal push per unit horizontal joint force (6.3).
        const double a = sin_alpha + tan_bedding * cos_alpha;
        const double c = sin_alpha + tan_vertical * cos_alpha;
        // 6.5 written as a/(1 - a c) rather than 1/(1/a - c): finite at
        // a = 0 (alpha = -phi_h), singular only at self-locking.
        const double locking = 1. - a * c;
        if (locking <= Internal::singular_denominator)
          return Internal::no_finite_answer(Status::self_locking, block + 1);

        const double increment     = vertical_load * cos_alpha * a / locking;
        const double lateral_force = previous_lateral_force + increment;
        forces.lateral_force.push_back(lateral_force);
        forces.normal_force.push_back(vertical_load * cos_alpha +
                                      increment * c);
        forces.joint_shear.push_back(lateral_force * tan_vertical);
        forces.normal_force_offset.push_back(0.);
        previous_lateral_force = lateral_force;
      }
    if (!Internal::all_finite(forces))
      return Internal::no_finite_answer(Status::self_locking, 0);
    Internal::check_no_tension(forces);
    return forces;
  }
} // namespace FloorBlock::Analytic
