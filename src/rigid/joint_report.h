#pragma once

#include <rigid/joint_set.h>
#include <rigid/results.h>

#include <vector>

namespace FloorBlock::RigidBlocks
{
  /**
   * @brief Integrate the responses of every joint into forces, contact
   * length, peak and mean traction, state counts and resultants.
   * @param[in] with_profiles Also keep the point values.
   */
  std::vector<RigidJointReport>
  make_joint_reports(const JointSet       &joint_set,
                     const JointResponses &responses,
                     const bool            with_profiles);
} // namespace FloorBlock::RigidBlocks
