#pragma once

#include <compare/load_check.h>
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
    /** E of the blocks (Pa): sets Compare::check_load's round-off force. */
    double       youngs_modulus;
    /**
     * Cutbacks of an increment that failed for good (not among the
     * result's converged increments); 0 for a converged run.
     */
    unsigned int cutbacks_before_failure = 0;
  };

  /**
   * @brief fem.json: the final joint table (chapter numbering, units in the
   * keys), per-increment statistics, DoFs, wall time per stage and the
   * force-balance error. A run that stopped early reports its last
   * converged increment under the given status; its "cutbacks" include
   * context.cutbacks_before_failure.
   *
   * The relative force-balance error of an increment that carries no load
   * (Compare::check_load) divides round-off by round-off: such increments
   * report 0 with force_balance_status "no load", and every increment
   * reports its absolute imbalance |applied load + support reactions| in
   * N/m.
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

  /**
   * @brief Why an increment counts as unloaded, with its numbers: "the
   * applied load, the support reactions and every joint force are at most
   * ... N/m, ...".
   */
  std::string
  no_load_text(const Compare::LoadCheck &check);

  /**
   * @brief fem.json's force balance in words: "force balance error 1.2e-13
   * (3.4e-08 N/m)", "no load (force balance 2.1e-07 N/m, round-off)" or
   * "force balance: no increment".
   */
  std::string
  force_balance_text(const nlohmann::json &fem);

  /** @brief "stage 3 (uplift)" style name of a loading stage. */
  std::string
  stage_name(const Contact::LoadStage stage);
} // namespace FloorBlock::Output
