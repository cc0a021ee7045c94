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
                    const double                                distance)
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
                  const double                                tolerance,
                  const double                                from_at_least,
                  const double                                up_to)
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
                 const DistanceRange                        &range)
  {
    std::vector<Analytic::RadialSample> within;
    for (const auto &sample : samples)
      if (sample.distance >= range.from && sample.distance <= range.to)
        within.push_back(sample);
    return within;
  }

  Intensities
  intensities_with_exponents(const std::vector<Analytic::RadialSample> &samples,
                             const double lambda1,
                             const double lambda2)
  {
    // Normal equations of min sum ((K1 f1 + K2 f2 - t) / t)^2,
    // f = d^(lambda - 1), in the scaled basis g = f / t.
    double a11 = 0., a12 = 0., a22 = 0., b1 = 0., b2 = 0.;
    for (const auto &sample : samples)
      if (sample.traction > 0. && sample.distance > 0.)
        {
          const double g1 =
            std::pow(sample.distance, lambda1 - 1.) / sample.traction;
          const double g2 =
            std::pow(sample.distance, lambda2 - 1.) / sample.traction;
          a11 += g1 * g1;
          a12 += g1 * g2;
          a22 += g2 * g2;
          b1 += g1;
          b2 += g2;
        }
    const double determinant = a11 * a22 - a12 * a12;
    if (!(determinant > 1e-14 * a11 * a22))
      return {};
    return {(a22 * b1 - a12 * b2) / determinant,
            (a11 * b2 - a12 * b1) / determinant};
  }

  CornerFit
  fit_corner(const std::vector<Analytic::RadialSample> &samples,
             const DistanceRange                        &range,
             const CornerTheory                         &theory)
  {
    CornerFit fit;
    fit.range = range;
    const auto within = samples_within(samples, range);
    fit.one_term      = Analytic::one_term_fit(within);
    fit.two_terms     = Analytic::two_term_fit(within, theory.next_exponent);
    fit.intensity = intensities_with_exponents(within, theory.exponent,
                                                theory.next_exponent);
    fit.validity_distance =
      Analytic::one_term_validity_distance(fit.two_terms, 0.1);
    return fit;
  }
} // namespace FloorBlock::Corner
