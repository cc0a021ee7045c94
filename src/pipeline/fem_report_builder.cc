#include <compare/load_check.h>
#include <pipeline/fem_report_builder.h>

#include <fmt/format.h>

#include <algorithm>

namespace FloorBlock::Pipeline
{
  namespace
  {
    /** Status and text of the worst force balance, given what was left out. */
    void
    describe_balance(const std::size_t            n_increments,
                     const unsigned int           n_unloaded,
                     const double                 largest_round_off_force,
                     Output::ForceBalanceSummary &balance)
    {
      balance.status      = "ok";
      balance.status_text = fmt::format(
        "worst relative error over the {} increments that carry load",
        n_increments - n_unloaded);
      if (n_increments == 0)
        {
          balance.status      = "no increment";
          balance.status_text = "no increment converged: nothing to balance";
        }
      else if (n_unloaded == n_increments)
        {
          balance.status      = "no load";
          balance.status_text = fmt::format(
            "no increment carries load (the applied load, the support "
            "reactions and every joint force stay below the round-off of the "
            "elastic forces, at most {:.1e} N/m): a relative error of a zero "
            "load is undefined and reported as 0; the absolute error is the "
            "round-off",
            largest_round_off_force);
        }
      else if (n_unloaded > 0)
        balance.status_text +=
          fmt::format("; {} increments carry no load and are left out "
                      "(their relative error is reported as 0)",
                      n_unloaded);
    }
  } // namespace

  Output::FemReport
  make_fem_report(const Contact::SolveResult           &result,
                  const Parameters::ScenarioParameters &scene,
                  const std::string                    &model,
                  const bool                            converged,
                  const std::string                    &status_text,
                  const unsigned int                    cutbacks_before_failure)
  {
    Output::FemReport report;
    report.model            = model;
    report.model_choice     = scene.model.choice_reason;
    report.status           = converged ? "converged" : "not converged";
    report.status_text      = status_text;
    report.n_blocks         = scene.geometry.n_blocks;
    report.support_width    = scene.geometry.support_width;
    report.n_cutbacks       = cutbacks_before_failure;
    unsigned int n_unloaded = 0;
    double       largest_round_off_force = 0.; // N/m
    for (const auto &increment : result.increments)
      {
        report.n_newton_iterations += increment.n_newton_iterations;
        report.n_cutbacks += increment.n_cutbacks;
        const Compare::LoadCheck load =
          Compare::check_load(increment, scene.material.youngs_modulus());
        const Output::IncrementBalance balance{
          load.carries_load() ? increment.balance.relative_imbalance : 0.,
          (increment.balance.applied_load + increment.balance.support_reaction)
            .norm(),
          load.carries_load()};
        report.increment_balances.push_back(balance);
        auto &worst = report.force_balance;
        worst.worst_relative_error =
          std::max(worst.worst_relative_error, balance.relative_error);
        worst.worst_absolute_error =
          std::max(worst.worst_absolute_error, balance.absolute_error);
        n_unloaded += balance.carries_load ? 0 : 1;
        largest_round_off_force =
          std::max(largest_round_off_force, load.round_off_force);
      }
    describe_balance(result.increments.size(),
                     n_unloaded,
                     largest_round_off_force,
                     report.force_balance);
    return report;
  }
} // namespace FloorBlock::Pipeline
