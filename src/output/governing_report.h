#pragma once

#include <compare/governing_joints.h>
#include <contact/results.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /**
   * @brief summary.json's "governing_joints": per figure the joint with the
   * largest value, where, and the face joint's value (units in the keys).
   */
  nlohmann::json
  governing_json(const std::vector<Compare::GoverningJoint> &governing);

  /**
   * @brief report.md's table of the governing joints beside the face
   * joint, after the face joint's verdicts.
   */
  std::string
  governing_table_markdown(
    const std::vector<Compare::GoverningJoint> &governing);

  /**
   * @brief The terminal's lines: one per figure that another joint than
   * the face joint governs, or one line saying the face joint governs all.
   */
  std::string
  governing_lines(const std::vector<Compare::GoverningJoint> &governing);

  /**
   * @brief gnuplot: along the floor lift (uplift increments of @p result,
   * lift = stage factor x @p floor_lift), the face joint's averaged and
   * pointwise peak stress against the largest over all joints; empty if
   * the solve has no uplift increment.
   */
  std::string
  governing_lift_plot(const Contact::SolveResult &result,
                      unsigned int                n_blocks,
                      double                      floor_lift);
} // namespace FloorBlock::Output
