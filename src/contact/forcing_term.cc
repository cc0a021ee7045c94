#include <contact/forcing_term.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Contact
{
  double
  forcing_term(const ForcingSettings &settings,
               const double           residual,
               const double           previous_residual,
               const double           previous_forcing,
               const double           stop_residual)
  {
    double eta = settings.first;
    if (previous_residual > 0. && residual > 0.)
      {
        eta = settings.gamma *
              std::pow(residual / previous_residual, settings.alpha);
        // Safeguard: a single lucky step must not make the next solve
        // much tighter than the convergence so far supports.
        const double from_previous =
          settings.gamma * std::pow(previous_forcing, settings.alpha);
        if (from_previous > 0.1)
          eta = std::max(eta, from_previous);
        eta = std::min(eta, settings.maximum);
      }
    // Oversolving guard: a linear residual of half the stop residual
    // already lets the next iterate pass the Newton test.
    if (residual > 0.)
      eta = std::max(eta, 0.5 * stop_residual / residual);
    return std::min(eta, settings.maximum);
  }
} // namespace FloorBlock::Contact
