#pragma once

#include <rigid/block_motion.h>
#include <rigid/joint_set.h>

#include <vector>

namespace FloorBlock::RigidBlocks
{
  /**
   * @brief Start guess of an uplift increment: every block carried along by
   * the base, i.e. the last converged motion plus the rigid motion that
   * fits the base displacement increment at the two ends of its bedding.
   *
   * For the rigid base motions (translations, tilt) this is what a block
   * stuck to the base does; for the parabola it is the chord of the
   * bending under the block. Without it, the first Newton iterate of an
   * increment sees the whole base step as overlap (kn x uplift, 1e3-1e4
   * times the loads) and the active set swings through most states before
   * it settles. Only the start changes: the converged state solves the
   * same equations.
   *
   * @param[in] joint_set Joints (the bedding joints give the end points).
   * @param[in] motions Last converged motions.
   * @param[in] previous_uplift Uplift factor of those motions (-).
   * @param[in] target_uplift Uplift factor of the increment (-).
   */
  std::vector<BlockMotion>
  predict_motions(const JointSet                 &joint_set,
                  const std::vector<BlockMotion> &motions,
                  const double                    previous_uplift,
                  const double                    target_uplift);
} // namespace FloorBlock::RigidBlocks
