#include <loading/load_path.h>

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace FloorBlock::Loading
{
  namespace
  {
    /**
     * A scripted model: fails where @p fails says so, and logs every
     * attempt, commit and discard.
     */
    struct ScriptedModel
    {
      std::function<bool(const LoadState &)> fails = [](const LoadState &) {
        return false;
      };
      std::vector<LoadState>   attempts;
      std::vector<LoadState>   commits;
      std::vector<std::string> discards;
      unsigned int             n_safe_points = 0;

      LoadPathCallbacks
      callbacks()
      {
        LoadPathCallbacks callbacks;
        callbacks.solve = [this](const LoadState &state,
                                 const FailedStartRecorder &,
                                 std::string &reason) {
          attempts.push_back(state);
          if (fails(state))
            {
              reason = "scripted failure";
              return false;
            }
          return true;
        };
        callbacks.commit = [this](const LoadState &state) {
          commits.push_back(state);
        };
        callbacks.discard = [this](const std::string &attempt) {
          discards.push_back(attempt);
        };
        callbacks.at_safe_point = [this]() { ++n_safe_points; };
        return callbacks;
      }
    };

    LoadSteps
    steps(const unsigned int n_gravity,
          const unsigned int n_pressure,
          const unsigned int n_uplift)
    {
      LoadSteps steps;
      steps.n_gravity  = n_gravity;
      steps.n_pressure = n_pressure;
      steps.n_uplift   = n_uplift;
      return steps;
    }

    std::vector<double>
    stage_factors_of(const std::vector<LoadState> &states)
    {
      std::vector<double> factors;
      for (const LoadState &state : states)
        factors.push_back(state.stage_factor);
      return factors;
    }
  } // namespace

  // The tool shall halve a failed step and grow it back to the nominal
  // step once increments converge again.
  TEST(LoadPath, GrowsBackAfterCutback)
  {
    ScriptedModel model;
    model.fails = [](const LoadState &state) {
      return state.stage_factor == 0.5 && state.n_cutbacks == 0;
    };
    const LoadPathOutcome outcome =
      follow_load_path(steps(4, 0, 0), 6, model.callbacks());

    EXPECT_TRUE(outcome.completed);
    EXPECT_EQ(stage_factors_of(model.attempts),
              (std::vector<double>{0.25, 0.5, 0.375, 0.625, 0.875, 1.}));
    EXPECT_EQ(stage_factors_of(model.commits),
              (std::vector<double>{0.25, 0.375, 0.625, 0.875, 1.}));
    EXPECT_EQ(model.commits[1].n_cutbacks, 1u);
    EXPECT_EQ(model.commits[2].n_cutbacks, 0u);
    EXPECT_EQ(model.commits[2].step, 0.25);
    ASSERT_EQ(model.discards.size(), 1u);
    EXPECT_EQ(outcome.failed_attempts,
              (std::vector<std::string>{
                "gravity factor 0.5 (step 0.25): scripted failure"}));
    EXPECT_EQ(model.discards, outcome.failed_attempts);
  }

  // The tool shall give up an increment after the allowed cutbacks and
  // list every failed attempt.
  TEST(LoadPath, GivesUpAfterMaxCutbacks)
  {
    ScriptedModel model;
    model.fails = [](const LoadState &state) {
      return state.stage == LoadStage::support_pressure;
    };
    const LoadPathOutcome outcome =
      follow_load_path(steps(1, 1, 1), 2, model.callbacks());

    EXPECT_FALSE(outcome.completed);
    EXPECT_EQ(outcome.failed_stage, LoadStage::support_pressure);
    EXPECT_EQ(outcome.failure_reason, "scripted failure");
    EXPECT_EQ(outcome.failed_attempts,
              (std::vector<std::string>{
                "support load factor 1 (step 1): scripted failure",
                "support load factor 0.5 (step 0.5): scripted failure",
                "support load factor 0.25 (step 0.25): scripted failure"}));
    EXPECT_EQ(model.discards, outcome.failed_attempts);
    ASSERT_EQ(model.commits.size(), 1u);
    EXPECT_EQ(model.commits[0].stage, LoadStage::gravity);
    // No attempt of the uplift stage after the path was given up.
    EXPECT_EQ(model.attempts.back().stage, LoadStage::support_pressure);
    EXPECT_EQ(model.n_safe_points, model.attempts.size());
  }

  // The tool shall end a stage of ten steps of 0.1 after ten increments:
  // their sum, 0.9999999999999999, is the stage end.
  TEST(LoadPath, RoundOffRemainderIsStageEnd)
  {
    ScriptedModel         model;
    const LoadPathOutcome outcome =
      follow_load_path(steps(0, 0, 10), 6, model.callbacks());

    EXPECT_TRUE(outcome.completed);
    ASSERT_EQ(model.commits.size(), 10u);
    EXPECT_EQ(model.commits.back().stage_factor, 1.);
    EXPECT_EQ(model.commits.back().factors.uplift, 1.);
  }

  // The tool shall skip stages without increments, and the gravity stage
  // when gravity rises with the support load.
  TEST(LoadPath, SkipsStagesWithoutIncrements)
  {
    ScriptedModel model;
    follow_load_path(steps(0, 2, 0), 6, model.callbacks());
    ASSERT_EQ(model.commits.size(), 2u);
    for (const LoadState &state : model.commits)
      {
        EXPECT_EQ(state.stage, LoadStage::support_pressure);
        EXPECT_EQ(state.factors.gravity, 1.);
      }

    ScriptedModel together;
    LoadSteps     with_gravity         = steps(3, 2, 0);
    with_gravity.gravity_with_pressure = true;
    follow_load_path(with_gravity, 6, together.callbacks());
    ASSERT_EQ(together.commits.size(), 2u);
    EXPECT_EQ(together.commits[0].stage, LoadStage::support_pressure);
    EXPECT_EQ(together.commits[0].factors.gravity, 0.5);
    EXPECT_EQ(together.commits[0].factors.support, 0.5);

    ScriptedModel nothing;
    EXPECT_TRUE(
      follow_load_path(steps(0, 0, 0), 6, nothing.callbacks()).completed);
    EXPECT_TRUE(nothing.attempts.empty());
  }

  // The tool shall extrapolate only within a stage: the predictor ratio is
  // 0 at each stage's first increment and step / last converged step after.
  TEST(LoadPath, PredictionRatioResetsAtStageStart)
  {
    ScriptedModel model;
    model.fails = [](const LoadState &state) {
      return state.stage == LoadStage::uplift && state.stage_factor == 0.5 &&
             state.n_cutbacks == 0;
    };
    follow_load_path(steps(2, 2, 4), 6, model.callbacks());

    std::vector<double> ratios;
    for (const LoadState &state : model.attempts)
      ratios.push_back(state.prediction_ratio);
    // gravity 0.5, 1; support 0.5, 1; uplift 0.25, 0.5 (fails), 0.375,
    // 0.625, 0.875, 1.
    EXPECT_EQ(ratios,
              (std::vector<double>{0., 1., 0., 1., 0., 1., 0.5, 2., 1., 0.5}));
  }

  // The tool shall list a failed start of a solver that retries within
  // the increment, without counting it as a cutback.
  TEST(LoadPath, FailedStartIsNoCutback)
  {
    LoadPathCallbacks        callbacks;
    std::vector<std::string> discards;
    std::vector<LoadState>   commits;
    callbacks.solve = [](const LoadState           &state,
                         const FailedStartRecorder &record_failed_start,
                         std::string &) {
      if (state.prediction_ratio > 0.)
        record_failed_start("extrapolated start", "cycling");
      return true;
    };
    callbacks.commit = [&](const LoadState &state) {
      commits.push_back(state);
    };
    callbacks.discard = [&](const std::string &attempt) {
      discards.push_back(attempt);
    };
    const LoadPathOutcome outcome =
      follow_load_path(steps(2, 0, 0), 0, callbacks);

    EXPECT_TRUE(outcome.completed);
    ASSERT_EQ(commits.size(), 2u);
    EXPECT_EQ(commits[1].n_cutbacks, 0u);
    EXPECT_EQ(outcome.failed_attempts,
              (std::vector<std::string>{
                "gravity factor 1 (step 0.5, extrapolated start): cycling"}));
    EXPECT_EQ(discards, outcome.failed_attempts);
  }
} // namespace FloorBlock::Loading
