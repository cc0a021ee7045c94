#include <fmt/format.h>
#include <refinement/ladder_budget.h>

#include <cmath>

namespace FloorBlock::Refinement
{
  LevelForecast
  forecast_next_level(const std::vector<LevelRecord> &levels)
  {
    const LevelRecord &last = levels.back();
    if (levels.size() >= 2)
      {
        const LevelRecord &previous = levels[levels.size() - 2];
        // A level that failed early has no meaningful size or time: fall
        // back to the first-step rule rather than divide by zero.
        if (previous.n_dofs > 0 && previous.wall_time > 0.)
          {
            const double dof_growth =
              std::max(1., double(last.n_dofs) / double(previous.n_dofs));
            const double time_growth =
              std::max(1., last.wall_time / previous.wall_time);
            return {last.n_dofs * dof_growth, last.wall_time * time_growth};
          }
      }
    return {last.n_dofs * first_step_dof_growth,
            last.wall_time *
              std::pow(first_step_dof_growth, first_step_time_exponent)};
  }

  std::optional<std::string>
  budget_stop_reason(const LadderBudget  &budget,
                     const double         spent_seconds,
                     const LevelForecast &forecast)
  {
    if (forecast.n_dofs > double(budget.max_dofs))
      return fmt::format("the next level would have about {:.0f} DoFs, "
                         "above --max-dofs {}",
                         forecast.n_dofs,
                         budget.max_dofs);
    const double left = budget.seconds - spent_seconds;
    if (forecast.wall_time > left)
      return fmt::format("the next level would take about {:.0f} s, {:.0f} s "
                         "of the --budget-seconds are left",
                         forecast.wall_time,
                         std::max(0., left));
    return std::nullopt;
  }
} // namespace FloorBlock::Refinement
