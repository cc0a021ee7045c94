#include <contact/newton_driver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace FloorBlock::Contact
{
  NewtonReport
  solve_newton(const NewtonSettings  &settings,
               const double           reference_force,
               const NewtonCallbacks &callbacks,
               const ReferenceForce   reference_kind)
  {
    NewtonReport  report;
    NewtonIterate current = callbacks.assemble();
    const double  first_residual =
      reference_kind == ReferenceForce::given_or_first_residual ?
         current.residual_norm :
         0.;
    // A zero load and zero first residual means nothing to do; the
    // smallest normal double keeps the ratio finite.
    const double reference = std::max(
      {reference_force, first_residual, std::numeric_limits<double>::min()});
    std::map<std::uint64_t, unsigned int> revisits;
    const double stop_residual     = settings.relative_tolerance * reference;
    double       previous_residual = 0.; // none before the first step
    double       forcing           = settings.forcing.maximum;
    report.counts                  = current.counts;
    report.relative_residual       = current.residual_norm / reference;

    for (unsigned int iteration = 1; iteration <= settings.max_iterations;
         ++iteration)
      {
        report.n_iterations = iteration;
        std::string message;
        forcing = forcing_term(settings.forcing,
                               current.residual_norm,
                               previous_residual,
                               forcing,
                               stop_residual);
        if (!callbacks.solve_update(forcing, message))
          {
            report.failure_reason = "linear solver failed: " + message;
            return report;
          }
        const NewtonIterate previous = current;
        previous_residual            = current.residual_norm;
        double step                  = 1.;
        bool   accepted              = false;
        for (unsigned int search = 0;
             search <= settings.max_line_search_steps && !accepted;
             ++search)
          {
            callbacks.set_step(step);
            current  = callbacks.assemble();
            accepted = std::isfinite(current.residual_norm) &&
                       current.residual_norm <=
                         (1. - settings.sufficient_decrease * step) *
                           previous.residual_norm;
            if (!accepted)
              step *= settings.line_search_reduction;
          }
        if (!accepted)
          {
            // No descent along the update: the set changes non-smoothly;
            // take the full semi-smooth Newton step.
            callbacks.set_step(1.);
            current = callbacks.assemble();
          }
        report.counts            = current.counts;
        report.relative_residual = current.residual_norm / reference;
        if (!std::isfinite(current.residual_norm))
          {
            report.failure_reason = "non-finite residual";
            return report;
          }
        const bool set_stable = current.set_signature == previous.set_signature;
        const bool within_tolerance =
          report.relative_residual <= settings.relative_tolerance;
        if (set_stable && within_tolerance)
          {
            report.converged = true;
            return report;
          }
        // A set that still changes while the residual is down to what
        // round-off alone produces: the pairs that change sit on a kink of
        // their law (a stuck pair exactly on the Coulomb cone with zero
        // slip rate), where both states give the same residual and
        // round-off picks one. Iterating on only flips them back and forth.
        if (!set_stable && within_tolerance && callbacks.round_off_floor &&
            current.residual_norm <= callbacks.round_off_floor())
          {
            report.converged = true;
            return report;
          }
        if (set_stable && callbacks.round_off_floor &&
            report.relative_residual <=
              settings.max_round_off_relief * settings.relative_tolerance &&
            current.residual_norm <= callbacks.round_off_floor())
          {
            report.converged                  = true;
            report.stopped_at_round_off_floor = true;
            return report;
          }
        if (!set_stable &&
            ++revisits[current.set_signature] > settings.cycling_limit)
          {
            report.failure_reason = "active-set cycling";
            return report;
          }
      }
    report.failure_reason = "no convergence within the iteration limit";
    return report;
  }
} // namespace FloorBlock::Contact
