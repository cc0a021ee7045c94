#include <rigid/force_balance.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace FloorBlock::RigidBlocks
{
  double
  relative_imbalance(const JointSet                      &joint_set,
                     const std::vector<RigidJointReport> &reports,
                     const std::vector<BlockLoads>       &loads,
                     const double                         gravity_factor,
                     const double                         support_factor,
                     const double                         block_width)
  {
    const unsigned int                n_blocks = joint_set.n_blocks();
    std::vector<dealii::Tensor<1, 2>> force_sum(n_blocks);
    std::vector<double>               moment_sum(n_blocks, 0.);
    double                            reference = 0.;

    for (unsigned int index = 0; index < n_blocks; ++index)
      {
        const std::array<double, 3> applied =
          applied_force(loads[index], gravity_factor, support_factor);
        const dealii::Point<2> &centroid = loads[index].centroid;
        force_sum[index] = dealii::Tensor<1, 2>({applied[0], applied[1]});
        // Moment about the origin = moment about the centroid + c x F.
        moment_sum[index] =
          applied[2] + centroid[0] * applied[1] - centroid[1] * applied[0];
        reference += std::hypot(applied[0], applied[1]);
      }

    const std::vector<JointGeometry> &joints = joint_set.joints();
    for (unsigned int j = 0; j < joints.size(); ++j)
      {
        reference = std::max(reference, reports[j].force_on_side_b.norm());
        const std::array<std::pair<BodyRef, double>, 2> sides = {
          {std::make_pair(joints[j].side_a, -1.),
           std::make_pair(joints[j].side_b, 1.)}};
        for (const auto &[body, sign] : sides)
          if (body.kind == BodyKind::block)
            {
              force_sum[body.index] += sign * reports[j].force_on_side_b;
              moment_sum[body.index] += sign * reports[j].moment_on_side_b;
            }
      }

    // Nothing loaded and nothing touching: the balance is trivially exact.
    reference    = std::max(reference, std::numeric_limits<double>::min());
    double worst = 0.;
    for (unsigned int index = 0; index < n_blocks; ++index)
      worst =
        std::max({worst,
                  force_sum[index].norm() / reference,
                  std::abs(moment_sum[index]) / (reference * block_width)});
    return worst;
  }
} // namespace FloorBlock::RigidBlocks
