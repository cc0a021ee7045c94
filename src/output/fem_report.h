#pragma once

#include <contact/results.h>

#include <nlohmann/json.hpp>

#include <string>

namespace FloorBlock::Output
{
  /** What the FEM report needs besides the solver's own results. */
  struct FemReportContext
  {
    unsigned int n_blocks;
    double       support_width; ///< b (m): areas and forces "over b"
    std::string  status;        ///< "converged" or "not converged"
    std::string  status_text;   ///< why, in words
  };

  /**
   * @brief fem.json: the final joint table (chapter numbering, units in the
   * keys), per-increment statistics, DoFs, wall time per stage and the
   * force-balance error. A run that stopped early reports its last
   * converged increment under the given status.
   */
  nlohmann::json
  fem_json(const Contact::SolveResult &result,
           const FemReportContext &    context);

  /** @brief One joint as the JSON object of fem.json's "joints" list. */
  nlohmann::json
  joint_json(const Contact::JointReport &joint,
             const FemReportContext &    context);

  /** @brief joints.csv: one row per joint per converged increment. */
  std::string
  joints_csv(const Contact::SolveResult &result,
             const FemReportContext &    context);

  /**
   * @brief The two bodies a joint separates, chapter numbering: [j, j+1] or
   * [n, "face"] for vertical joint j, [i, "base"] for the bedding under i.
   */
  nlohmann::json
  joint_bodies(const std::string &kind,
               const unsigned int number,
               const unsigned int n_blocks);

  /** @brief "stage 3 (uplift)" style name of a loading stage. */
  std::string
  stage_name(const Contact::LoadStage stage);
} // namespace FloorBlock::Output
