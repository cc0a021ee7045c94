#include <corner/corner_fit.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Corner
{
  namespace
  {
    /** log t at log d, linear in log-log between @p samples (sorted by d); NaN outside. */
    double
    log_traction_at(const std::vector<Analytic::RadialSample> &samples,
                    const double                               distance)
    {
      for (std::size_t k = 1; k < samples.size(); ++k)
        if (samples[k - 1].distance <= distance &&
            distance <= samples[k].distance)
          {
            const auto &a = samples[k - 1], &b = samples[k];
            if (!(a.traction > 0. && b.traction > 0.))
              return std::nan("");
            const double w = std::log(distance / a.distance) /
                             std::log(b.distance / a.distance);
            return (1. - w) * std::log(a.traction) + w * std::log(b.traction);
          }
      return std::nan("");
    }

    constexpr unsigned int smallest_run = 4;
  } // namespace

  DistanceRange
  converged_range(const std::vector<Analytic::RadialSample> &fine,
                  const std::vector<Analytic::RadialSample> &coarse,
                  const double                               tolerance,
                  const double                               from_at_least,
                  const double                               up_to)
  {
    DistanceRange best, current;
    for (const auto &sample : fine)
      {
        if (sample.distance < from_at_least || sample.distance > up_to)
          continue;
        const double reference = log_traction_at(coarse, sample.distance);
        const bool   agrees =
          sample.traction > 0. && std::isfinite(reference) &&
          std::abs(sample.traction / std::exp(reference) - 1.) <= tolerance;
        if (agrees)
          {
            if (current.n_samples == 0)
              current.from = sample.distance;
            current.to = sample.distance;
            ++current.n_samples;
            if (current.n_samples > best.n_samples)
              best = current;
          }
        else
          current = DistanceRange{};
      }
    return best.n_samples >= smallest_run ? best : DistanceRange{};
  }

  std::vector<Analytic::RadialSample>
  samples_within(const std::vector<Analytic::RadialSample> &samples,
                 const DistanceRange                       &range)
  {
    std::vector<Analytic::RadialSample> within;
    for (const auto &sample : samples)
      if (sample.distance >= range.from && sample.distance <= range.to)
        within.push_back(sample);
    return within;
  }

  namespace
  {
    /** The theory's further exponents: next and, if any, third. */
    std::vector<double>
    further_exponents(const CornerTheory &theory)
    {
      std::vector<double> further{theory.next_exponent};
      if (theory.third_exponent > theory.next_exponent)
        further.push_back(theory.third_exponent);
      return further;
    }
  } // namespace

  Intensities
  theory_intensities(const std::vector<Analytic::RadialSample> &samples,
                     const CornerTheory                        &theory)
  {
    std::vector<double> exponents{theory.exponent};
    for (const double further : further_exponents(theory))
      exponents.push_back(further);
    const Analytic::AsymptoticFit fit =
      Analytic::fixed_exponent_fit(samples, exponents);
    if (!std::isfinite(fit.rms_relative_residual))
      return {};
    return {fit.k1, fit.k2};
  }

  Analytic::AsymptoticFit
  fit_invariant(const std::vector<Analytic::RadialSample> &samples,
                const DistanceRange                       &range,
                const CornerTheory                        &theory)
  {
    std::vector<double> further = further_exponents(theory);
    // Scan between the neighbouring known exponents, clear of both: next
    // to the constant (lambda = 1) the term d^(lambda1 - 1) ~ 1 +
    // (lambda1 - 1) ln d merges with it.
    double below = 0.;
    if (theory.exponent > 1.)
      {
        further.insert(further.begin(), 1.);
        below = 1.;
      }
    const double gap = theory.next_exponent - below;
    return Analytic::expansion_fit(samples_within(samples, range),
                                   further,
                                   below + 0.02 * gap,
                                   theory.next_exponent - 0.02 * gap);
  }

  CornerFit
  fit_corner(const std::vector<Analytic::RadialSample> &samples,
             const DistanceRange                       &range,
             const CornerTheory                        &theory)
  {
    CornerFit fit;
    fit.range         = range;
    const auto within = samples_within(samples, range);
    fit.one_term      = Analytic::one_term_fit(within);
    fit.two_terms     = Analytic::two_term_fit(within, theory.next_exponent);
    fit.expansion     = Analytic::expansion_fit(within,
                                            further_exponents(theory),
                                            0.01,
                                            theory.next_exponent - 0.01);
    fit.intensity     = theory_intensities(within, theory);
    fit.validity_distance =
      Analytic::one_term_validity_distance(fit.expansion, 0.1);
    return fit;
  }
} // namespace FloorBlock::Corner
