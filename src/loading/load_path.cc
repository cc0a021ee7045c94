#include <loading/load_path.h>

#include <algorithm>
#include <sstream>
#include <utility>

namespace FloorBlock::Loading
{
  namespace
  {
    /**
     * Fraction of a stage treated as its end (-): ten steps of 0.1 sum to
     * 0.9999999999999999, and the round-off remainder must not become an
     * increment of its own (a zero load step re-tests every slipping pair
     * exactly on its Coulomb limit, where the stick/slip decision is
     * round-off and the active set can cycle).
     */
    constexpr double stage_end_tolerance = 1e-12;

    std::string
    attempt_line(const LoadState   &state,
                 const std::string &start,
                 const std::string &reason)
    {
      std::ostringstream line;
      line << stage_name(state.stage) << " factor " << state.stage_factor
           << " (step " << state.step;
      if (!start.empty())
        line << ", " << start;
      line << "): " << reason;
      return line.str();
    }

    /** The increments of one stage; false if the stage was given up. */
    bool
    follow_stage(const LoadStage          stage,
                 const unsigned int       n_increments,
                 const bool               gravity_with_support,
                 const unsigned int       max_cutbacks,
                 const LoadPathCallbacks &callbacks,
                 LoadPathOutcome         &outcome)
    {
      const double nominal_step = 1. / n_increments;
      double       reached      = 0.;
      double       step         = nominal_step;
      // Step of the last converged increment; 0: none yet this stage.
      double       last_step = 0.;
      unsigned int n_failed  = 0;
      while (reached < 1.)
        {
          if (callbacks.at_safe_point)
            callbacks.at_safe_point();
          LoadState state;
          state.stage = stage;
          state.stage_factor =
            reached + step >= 1. - stage_end_tolerance ? 1. : reached + step;
          state.step = step;
          state.factors =
            stage_factors(stage, state.stage_factor, gravity_with_support);
          state.prediction_ratio =
            last_step > 0. ? (state.stage_factor - reached) / last_step : 0.;
          state.n_cutbacks = n_failed;

          const auto record_failure = [&](const std::string &start,
                                          const std::string &reason) {
            outcome.failed_attempts.push_back(
              attempt_line(state, start, reason));
            callbacks.discard(outcome.failed_attempts.back());
          };
          std::string reason;
          if (callbacks.solve(state, record_failure, reason))
            {
              callbacks.commit(state);
              last_step = state.stage_factor - reached;
              reached   = state.stage_factor;
              n_failed  = 0;
              // Grow back after a cutback, never beyond the nominal step.
              step = std::min(nominal_step, 2. * step);
              continue;
            }
          record_failure("", reason);
          if (++n_failed > max_cutbacks)
            {
              outcome.completed      = false;
              outcome.failed_stage   = stage;
              outcome.failure_reason = reason;
              return false;
            }
          step /= 2.;
        }
      return true;
    }
  } // namespace

  LoadPathOutcome
  follow_load_path(const LoadSteps         &steps,
                   const unsigned int       max_cutbacks,
                   const LoadPathCallbacks &callbacks)
  {
    // Gravity rising with the support load has no stage of its own.
    const std::pair<LoadStage, unsigned int> stages[] = {
      {LoadStage::gravity, steps.gravity_with_pressure ? 0 : steps.n_gravity},
      {LoadStage::support_pressure, steps.n_pressure},
      {LoadStage::uplift, steps.n_uplift}};
    LoadPathOutcome outcome;
    for (const auto &[stage, n_increments] : stages)
      if (n_increments > 0 && !follow_stage(stage,
                                            n_increments,
                                            steps.gravity_with_pressure,
                                            max_cutbacks,
                                            callbacks,
                                            outcome))
        break;
    return outcome;
  }
} // namespace FloorBlock::Loading
