#include <analytic/chain_checks.h>

#include <cmath>

namespace FloorBlock::Analytic
{
  namespace Internal
  {
    ChainForces
    no_finite_answer(const Status status, const std::size_t block_number)
    {
      ChainForces forces;
      forces.status        = status;
      forces.failing_block = block_number;
      return forces;
    }

    void
    check_no_tension(ChainForces &forces)
    {
      if (forces.status != Status::ok)
        return;
      for (std::size_t block = 0; block < forces.lateral_force.size(); ++block)
        {
          const bool opens = forces.lateral_force[block] < 0.;
          const bool lifts = forces.normal_force[block] < 0.;
          if (opens || lifts)
            {
              forces.status =
                opens ? Status::joint_opens : Status::base_lifts_off;
              forces.failing_block = block + 1;
              return;
            }
        }
    }

    bool
    all_finite(const ChainForces &forces)
    {
      for (const std::vector<double> *values : {&forces.lateral_force,
                                                &forces.normal_force,
                                                &forces.joint_shear,
                                                &forces.normal_force_offset})
        for (const double value : *values)
          if (!std::isfinite(value))
            return false;
      return true;
    }
  } // namespace Internal
} // namespace FloorBlock::Analytic
