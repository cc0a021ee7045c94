#include <analytic/centroid_heights.h>

#include <cmath>

namespace FloorBlock::Analytic
{
  CentroidHeights
  centroid_heights(const BlockChain          &chain,
                   const std::vector<double> &lateral_force)
  {
    CentroidHeights result;
    if (validate(chain) != Status::ok ||
        lateral_force.size() != chain.n_blocks())
      {
        result.status = Status::invalid_input;
        return result;
      }

    const double width        = chain.block_width;
    const double tan_vertical = std::tan(chain.vertical_friction);
    // Running moment Q_i h_i about the uphill base corner (N m / m).
    double moment_of_lateral_force = 0.;
    for (std::size_t block = 0; block < chain.n_blocks(); ++block)
      {
        const double force = lateral_force[block];
        if (!(force > 0.) || !std::isfinite(force))
          {
            CentroidHeights failed;
            failed.status        = Status::joint_opens;
            failed.failing_block = block + 1;
            return failed;
          }
        // The weight acts at mid-width, the support load at r L from the
        // uphill corner, the joint friction of the face-side neighbour at
        // L; the away-side joint friction passes through the corner.
        moment_of_lateral_force +=
          chain.weight[block] * width / 2. +
          chain.support_load[block] * chain.support_load_position * width +
          force * width * tan_vertical;
        const double height = moment_of_lateral_force / force;
        // Extreme but finite inputs can overflow the running moment (or
        // a tiny Q can blow up the quotient): no finite answer then.
        if (!std::isfinite(height))
          {
            CentroidHeights failed;
            failed.status        = Status::invalid_input;
            failed.failing_block = block + 1;
            return failed;
          }
        result.centroid_height.push_back(height);
        result.rotation_margin.push_back(chain.block_height - height);
        if (height > chain.block_height && result.first_rotating_block == 0)
          result.first_rotating_block = block + 1;
      }
    return result;
  }
} // namespace FloorBlock::Analytic
