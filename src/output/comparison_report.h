#pragma once

#include <compare/joint_comparison.h>
#include <compare/joint_states.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /** The face joint against Eqs. 6.51-6.53 at one uplift increment. */
  struct LiftHistoryPoint
  {
    double                   base_lift = 0.; ///< m, the increment's lift
    Compare::JointComparison face_joint;
    /** The floor's safety factors at the increment (may be empty). */
    std::vector<Contact::CornerFactors> corner_factors;
  };

  /** `run`'s comparison of the FEM with the closed forms. */
  struct RunComparison
  {
    /** Every vertical joint at the last converged increment. */
    std::vector<Compare::JointComparison> final_joints;
    /** The face joint at every converged uplift increment. */
    std::vector<LiftHistoryPoint> lift_history;
    Compare::ContactConstants     constants;
    /** What the closed forms were given, and how the scenes differ. */
    Compare::ClosedFormInputs inputs;
    /** The FEM's joints against their friction limits, last increment. */
    Compare::JointStates joint_states;
  };

  /** @brief summary.json's "comparison": {"final", "lift_history"}. */
  nlohmann::json
  run_comparison_json(const RunComparison &comparison,
                      const unsigned int   n_blocks);

  /** One record per vertical joint (the "comparison.final" list). */
  nlohmann::json
  comparison_json(const std::vector<Compare::JointComparison> &joints,
                  const Compare::ContactConstants             &constants,
                  const unsigned int                           n_blocks);

  /** The face-joint record of one uplift increment (for "lift_history"). */
  nlohmann::json
  lift_history_entry(const Compare::JointComparison  &face_joint,
                     const Compare::ContactConstants &constants,
                     const double                     base_lift);

  /**
   * @brief report.md's table of Q per vertical joint: the FEM's and each
   * closed form's (kN/m) with their relative difference, "-" where the
   * closed form has no value or the difference is undefined.
   */
  std::string
  force_table_markdown(const std::vector<Compare::JointComparison> &joints,
                       const unsigned int                           n_blocks);

  /**
   * @brief report.md's corner-contact table per vertical joint: y, the
   * contact area and stresses of the FEM against Eqs. 6.51-6.53, status.
   */
  std::string
  contact_table_markdown(const std::vector<Compare::JointComparison> &joints);

  /**
   * @brief The closed forms' inputs in one sentence (alpha per block, W_i,
   * P_i, y), then one sentence per way the FEM's scene differs from theirs.
   */
  std::vector<std::string>
  closed_form_input_lines(const Compare::ClosedFormInputs &inputs);

  /**
   * @brief closed_form_input_lines(), then one sentence per quantity at the
   * face joint, e.g. "Eq. 6.51 underestimates the contact area by 23 % at
   * the face joint"; on a scene the closed forms do not describe, one
   * sentence that gives no verdict on Q instead of the percentages.
   */
  std::vector<std::string>
  verdicts(const RunComparison &comparison);

  /** gnuplot: Q per joint, FEM points against each closed form. */
  std::string
  force_per_joint_plot(const std::vector<Compare::JointComparison> &joints);

  /** gnuplot: contact area and sigma_max at the face joint vs base lift. */
  std::string
  lift_history_plot(const std::vector<LiftHistoryPoint> &lift_history);

  /** gnuplot: normal traction along the face joint at the final lift. */
  std::string
  traction_profile_plot(const Contact::JointReport &face_joint);
} // namespace FloorBlock::Output
