// converge's budget: forecasting the next level and stopping before one
// that would not fit.
#include <gtest/gtest.h>
#include <refinement/ladder_budget.h>

#include <cmath>

namespace
{
  using namespace FloorBlock::Refinement;

  LevelRecord
  level(const unsigned int n_dofs, const double wall_time)
  {
    LevelRecord record;
    record.n_dofs    = n_dofs;
    record.wall_time = wall_time;
    return record;
  }

  TEST(ForecastNextLevel, RepeatsTheLastStepsGrowth)
  {
    const LevelForecast forecast =
      forecast_next_level({level(5528, 0.7), level(20596, 3.4)});
    EXPECT_NEAR(forecast.n_dofs, 20596. * 20596. / 5528., 1e-9);
    EXPECT_NEAR(forecast.wall_time, 3.4 * 3.4 / 0.7, 1e-12);
  }

  TEST(ForecastNextLevel, FirstStepQuadruplesTheDofs)
  {
    const LevelForecast forecast = forecast_next_level({level(1000, 2.)});
    EXPECT_DOUBLE_EQ(forecast.n_dofs, 4000.);
    EXPECT_NEAR(forecast.wall_time,
                2. * std::pow(4., first_step_time_exponent),
                1e-12);
  }

  // A level that failed before it had a mesh (0 DoFs) or a time gives no
  // growth to repeat; a shrinking step (adaptive coarsening) is not
  // extrapolated downwards.
  TEST(ForecastNextLevel, NeverForecastsFromNothingOrBelowTheLastLevel)
  {
    const LevelForecast after_failure =
      forecast_next_level({level(0, 0.), level(1000, 2.)});
    EXPECT_DOUBLE_EQ(after_failure.n_dofs, 4000.);
    const LevelForecast after_shrink =
      forecast_next_level({level(2000, 3.), level(1000, 2.)});
    EXPECT_DOUBLE_EQ(after_shrink.n_dofs, 1000.);
    EXPECT_DOUBLE_EQ(after_shrink.wall_time, 2.);
  }

  TEST(BudgetStopReason, StopsOnTimeOrDofsAndSaysWhich)
  {
    LadderBudget budget;
    budget.seconds  = 60.;
    budget.max_dofs = 400000;
    EXPECT_FALSE(budget_stop_reason(budget, 20., {79400., 16.}));
    const auto on_time = budget_stop_reason(budget, 20., {312000., 70.});
    ASSERT_TRUE(on_time);
    EXPECT_NE(on_time->find("--budget-seconds"), std::string::npos);
    const auto on_dofs = budget_stop_reason(budget, 0., {1.2e6, 10.});
    ASSERT_TRUE(on_dofs);
    EXPECT_NE(on_dofs->find("--max-dofs"), std::string::npos);
  }
} // namespace
