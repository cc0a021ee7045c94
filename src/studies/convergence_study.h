#pragma once

#include <output/convergence_report.h>
#include <output/result_folder.h>

#include <refinement/equal_error.h>
#include <refinement/size_targets.h>
#include <studies/convergence_ladder.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Studies
{
  /** Target: adaptive needs at most this fraction of the uniform DoFs ... */
  constexpr double target_dofs_ratio = 0.25;
  /** ... and less than this fraction of its wall time. */
  constexpr double target_cost_ratio = 1.;

  /**
   * @brief The ladders of `converge --mode @p choice`: uniform, adaptive,
   * remesh, both (uniform and adaptive) or all.
   */
  std::vector<RefinementMode>
  refinement_modes(const std::string &choice);

  /**
   * @brief Every further ladder against the first (when it is the uniform
   * one), per quantity, at the relative error @p target_error.
   */
  std::vector<Refinement::EqualErrorComparison>
  equal_error_comparisons(const std::vector<Refinement::Ladder>   &ladders,
                          const std::vector<Refinement::Quantity> &quantities,
                          const double target_error);

  /**
   * @brief Whether the ladder @p adaptive_mode ("adaptive" or "remesh")
   * reaches the face joint's contact length and averaged peak stress at
   * the target error with at most target_dofs_ratio of the uniform DoFs in
   * less time; not evaluated without both ladders.
   */
  Output::TargetVerdict
  target_verdict(
    const std::vector<Refinement::EqualErrorComparison> &comparisons,
    const std::string                                   &adaptive_mode);
  /**
   * @brief One line per quantity comparing the uniform ladders of FE
   * degree 2 ("uniform_q2") and 1 ("uniform") at equal error: the level
   * each needs, DoFs and time ratio, and which degree gets there faster;
   * "" without a degree-2 ladder.
   */
  std::string
  degree_comparison_text(
    const std::vector<Refinement::EqualErrorComparison> &comparisons);

  /** What `converge` asks of its ladders. */
  struct StudySettings
  {
    /** FE degrees, each with its ladders; empty: the scene's degree. */
    std::vector<unsigned int> fe_degrees;
    /** uniform, adaptive, remesh, both or all (refinement_modes()). */
    std::string  refinement_mode = "both";
    unsigned int n_levels        = 5;
    /** Wall time of the whole study (s): each ladder gets what the ladders
     * before it left. Infinite: the levels are the budget. */
    double                         budget_seconds = 60.;
    unsigned int                   max_dofs       = 0;
    Refinement::RefinementSettings refinement;
    double                         coarsen_fraction = 0.;
    /** Relative error at which the ladders' costs are compared. */
    double target_error = 0.01;
  };

  /** The ladders of a study and what they show. */
  struct ConvergenceStudy
  {
    std::vector<Refinement::Quantity>             quantities;
    std::vector<Refinement::Ladder>               ladders;
    std::vector<Refinement::EqualErrorComparison> comparisons;
    /** Whether every level's solve converged. */
    bool                                 all_converged = true;
    Output::TargetVerdict                adaptive_target;
    std::optional<Output::TargetVerdict> remesh_target;
  };

  /** Called with each finished ladder and the quantities it estimates. */
  using LadderDone =
    std::function<void(const Refinement::Ladder &,
                       const std::vector<Refinement::Quantity> &)>;

  /**
   * @brief `converge`: each ladder of @p settings in turn on @p scene,
   * convergence.csv and convergence.json rewritten in @p folder after every
   * level (a stopped study keeps what it has), then the comparisons at
   * equal error, the verdicts, the final convergence.json and
   * error_vs_wall_time.png. @p ladder_done sees each finished ladder.
   */
  ConvergenceStudy
  run_convergence_study(const Parameters::ScenarioParameters &scene,
                        const StudySettings                  &settings,
                        const Output::ResultFolder           &folder,
                        const LadderDone                     &ladder_done);
} // namespace FloorBlock::Studies
