#pragma once

#include <contact/results.h>
#include <output/fem_error_estimate.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace FloorBlock::Output
{
  /**
   * @brief The face joint's FEM figures, each with its estimated relative
   * discretisation error and the time it cost: what a user reads as
   * "sigma_max = 15.7 MPa +- 0.1 % in 4.2 s".
   *
   * @param[in] solve The solve: its last converged increment's joints and
   *   its wall time per section.
   * @param[in] error_estimate The error estimate (may be absent or not
   *   available: the errors are then null with that status).
   * @param[in] n_blocks Face joint = "vertical n".
   * @return [{"quantity", "field", "value", "unit", "relative_error",
   *   "status" ("estimated" or "error not estimated"), "error_method",
   *   "wall_time_s"}]; wall_time_s is the FEM solve's, the
   *   same for every figure of one solve (they come out together).
   */
  nlohmann::json
  face_joint_figures(const Contact::SolveResult            &solve,
                     const std::optional<FemErrorEstimate> &error_estimate,
                     const unsigned int                     n_blocks);

  /** @brief One terminal line per figure of face_joint_figures(). */
  std::string
  figure_lines(const Contact::SolveResult            &solve,
               const std::optional<FemErrorEstimate> &error_estimate,
               const unsigned int                     n_blocks);
} // namespace FloorBlock::Output
