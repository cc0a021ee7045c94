#pragma once

#include <rigid/block_loads.h>
#include <rigid/joint_set.h>
#include <rigid/results.h>

#include <vector>

namespace FloorBlock::RigidBlocks
{
  /**
   * @brief Largest relative imbalance of a block, recomputed from the joint
   * resultants (RigidJointReport::force_on_side_b, moment_on_side_b) and the
   * applied loads, independently of the Newton residual.
   *
   * For every block: applied force + contact forces of its joints (as side
   * B, or their opposite as side A) = 0, and the same for moments about the
   * origin. The force error is divided by the reference force, the moment
   * error by the reference force times L; the reference is the larger of
   * the total applied load and the largest joint resultant.
   *
   * @return max over blocks of both ratios (-).
   */
  double
  relative_imbalance(const JointSet                      &joint_set,
                     const std::vector<RigidJointReport> &reports,
                     const std::vector<BlockLoads>       &loads,
                     const double                         gravity_factor,
                     const double                         support_factor,
                     const double                         block_width);
} // namespace FloorBlock::RigidBlocks
