#include <analytic/block_chain.h>

#include <cmath>

namespace FloorBlock::Analytic
{
  namespace
  {
    bool
    is_friction_angle(const double angle)
    {
      return std::isfinite(angle) && angle >= 0. && angle < M_PI_2;
    }
  } // namespace

  std::size_t
  BlockChain::n_blocks() const
  {
    return weight.size();
  }

  Status
  validate(const BlockChain &chain)
  {
    const std::size_t n_blocks = chain.n_blocks();
    if (n_blocks == 0 || chain.support_load.size() != n_blocks ||
        chain.inclination.size() != n_blocks)
      return Status::invalid_input;
    for (std::size_t block = 0; block < n_blocks; ++block)
      {
        const bool loads_ok = std::isfinite(chain.weight[block]) &&
                              std::isfinite(chain.support_load[block]) &&
                              chain.weight[block] >= 0. &&
                              chain.support_load[block] >= 0.;
        const bool inclination_ok = std::isfinite(chain.inclination[block]) &&
                                    std::abs(chain.inclination[block]) < M_PI_2;
        if (!loads_ok || !inclination_ok)
          return Status::invalid_input;
      }
    const bool sizes_ok = std::isfinite(chain.block_width) &&
                          std::isfinite(chain.block_height) &&
                          chain.block_width > 0. && chain.block_height > 0.;
    const bool position_ok = std::isfinite(chain.support_load_position) &&
                             chain.support_load_position >= 0. &&
                             chain.support_load_position <= 1.;
    if (!sizes_ok || !position_ok ||
        !is_friction_angle(chain.bedding_friction) ||
        !is_friction_angle(chain.vertical_friction))
      return Status::invalid_input;
    return Status::ok;
  }

  BlockChain
  uniform_chain(const std::size_t n_blocks,
                const double      weight,
                const double      support_load,
                const double      inclination,
                const double      block_width,
                const double      block_height,
                const double      bedding_friction,
                const double      vertical_friction)
  {
    BlockChain chain;
    chain.weight.assign(n_blocks, weight);
    chain.support_load.assign(n_blocks, support_load);
    chain.inclination.assign(n_blocks, inclination);
    chain.block_width       = block_width;
    chain.block_height      = block_height;
    chain.bedding_friction  = bedding_friction;
    chain.vertical_friction = vertical_friction;
    return chain;
  }
} // namespace FloorBlock::Analytic
