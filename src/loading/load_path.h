#pragma once

#include <loading/load_factors.h>
#include <loading/load_stage.h>
#include <loading/load_steps.h>

#include <functional>
#include <string>
#include <vector>

namespace FloorBlock::Loading
{
  /** @brief One load state to solve: where on the path and how far. */
  struct LoadState
  {
    LoadStage stage = LoadStage::gravity;
    /** Fraction of the stage's load at this state (-). */
    double stage_factor = 0.;
    /** Stage-factor step from the last converged state (-). */
    double      step = 0.;
    LoadFactors factors;
    /**
     * step over the step of the last converged increment of the same
     * stage: the multiple of that increment's change a linear predictor
     * adds to the last converged state. 0 for a stage's first increment
     * (no extrapolation across stages).
     */
    double prediction_ratio = 0.;
    /** Failed attempts of this increment so far (cutbacks). */
    unsigned int n_cutbacks = 0;
  };

  /**
   * Records a start that failed when the caller tries another start of the
   * same load state (not a cutback): @p start names it ("extrapolated
   * start"), @p reason says why it failed. The attempt is listed and
   * LoadPathCallbacks::discard runs before the call returns.
   */
  using FailedStartRecorder =
    std::function<void(const std::string &start, const std::string &reason)>;

  /**
   * @brief The model as seen by the load-path driver (in the style of
   * Contact::NewtonCallbacks): the driver never sees displacements.
   */
  struct LoadPathCallbacks
  {
    /**
     * Solve for equilibrium at @p state from the last converged state;
     * false with a reason on failure. A solver with several starts reports
     * each failed start but the last through the recorder.
     */
    std::function<bool(const LoadState           &state,
                       const FailedStartRecorder &record_failed_start,
                       std::string               &failure_reason)>
      solve;
    /** Accept the state just solved as the new converged state. */
    std::function<void(const LoadState &state)> commit;
    /**
     * After a failed attempt: return to the last converged state.
     * @p attempt is the record line of the failure (see LoadPathOutcome).
     */
    std::function<void(const std::string &attempt)> discard;
    /**
     * Optional: called before each attempt, where stopping loses nothing
     * (the interrupt check of a long solve).
     */
    std::function<void()> at_safe_point;
  };

  /** @brief How far the path was followed. */
  struct LoadPathOutcome
  {
    bool completed = true;
    /** The stage and last failure reason of a path given up. */
    LoadStage   failed_stage = LoadStage::gravity;
    std::string failure_reason;
    /**
     * One line per failed attempt, in order, also of a completed path:
     * "<stage> factor <f> (step <s>[, <start>]): <reason>".
     */
    std::vector<std::string> failed_attempts;
  };

  /**
   * @brief Follows the loading path gravity -> support load -> uplift, each
   * stage in its own increments, with cutback.
   *
   * A stage of n increments starts with the nominal step 1/n. A converged
   * increment is committed and the step grows back to min(1/n, 2 step);
   * a failed one is discarded and the step halved. The path is given up
   * when one increment has failed more than @p max_cutbacks times. A
   * stage with no increments is skipped, and so is the gravity stage when
   * gravity rises with the support load.
   *
   * @param[in] steps Increments per stage.
   * @param[in] max_cutbacks Halvings of one increment before giving up.
   * @param[in] callbacks The model.
   */
  LoadPathOutcome
  follow_load_path(const LoadSteps         &steps,
                   const unsigned int       max_cutbacks,
                   const LoadPathCallbacks &callbacks);
} // namespace FloorBlock::Loading
