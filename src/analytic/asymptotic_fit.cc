#include <analytic/asymptotic_fit.h>

#include <cmath>
#include <limits>

namespace FloorBlock::Analytic
{
  namespace
  {
    /** K1, K2 and the squared relative residual for a given lambda1. */
    AsymptoticFit
    project(const std::vector<RadialSample> &samples,
            const double                     lambda1,
            const double                     lambda2)
    {
      // Rows a_i = r^(l1-1)/p, b_i = r^(l2-1)/p; solve c1 a + c2 b ~ 1.
      double saa = 0., sbb = 0., sab = 0., sa = 0., sb = 0.;
      for (const RadialSample &s : samples)
        {
          const double a = std::pow(s.distance, lambda1 - 1.) / s.traction;
          const double b = std::pow(s.distance, lambda2 - 1.) / s.traction;
          saa += a * a;
          sbb += b * b;
          sab += a * b;
          sa += a;
          sb += b;
        }
      AsymptoticFit fit;
      fit.lambda1             = lambda1;
      fit.lambda2             = lambda2;
      fit.n_samples           = samples.size();
      const double determinant = saa * sbb - sab * sab;
      if (!(std::abs(determinant) > 0.))
        {
          fit.rms_relative_residual = std::numeric_limits<double>::infinity();
          return fit;
        }
      fit.k1 = (sa * sbb - sb * sab) / determinant;
      fit.k2 = (saa * sb - sab * sa) / determinant;
      double squares = 0.;
      for (const RadialSample &s : samples)
        {
          const double model = fit.k1 * std::pow(s.distance, lambda1 - 1.) +
                               fit.k2 * std::pow(s.distance, lambda2 - 1.);
          squares += std::pow((model - s.traction) / s.traction, 2);
        }
      fit.rms_relative_residual = std::sqrt(squares / samples.size());
      return fit;
    }

    std::vector<RadialSample>
    positive(const std::vector<RadialSample> &samples)
    {
      std::vector<RadialSample> kept;
      for (const RadialSample &s : samples)
        if (s.distance > 0. && s.traction > 0.)
          kept.push_back(s);
      return kept;
    }
  } // namespace

  AsymptoticFit
  one_term_fit(const std::vector<RadialSample> &all_samples)
  {
    const std::vector<RadialSample> samples = positive(all_samples);
    AsymptoticFit                   fit;
    fit.n_samples = samples.size();
    if (samples.size() < 2)
      return fit;
    double mean_x = 0., mean_y = 0.;
    for (const RadialSample &s : samples)
      {
        mean_x += std::log(s.distance) / samples.size();
        mean_y += std::log(s.traction) / samples.size();
      }
    double sxx = 0., sxy = 0.;
    for (const RadialSample &s : samples)
      {
        const double x = std::log(s.distance) - mean_x;
        sxx += x * x;
        sxy += x * (std::log(s.traction) - mean_y);
      }
    if (!(sxx > 0.))
      return fit;
    const double slope = sxy / sxx;
    fit.lambda1 = 1. + slope;
    fit.k1      = std::exp(mean_y - slope * mean_x);
    double squares = 0.;
    for (const RadialSample &s : samples)
      squares += std::pow(
        (fit.k1 * std::pow(s.distance, slope) - s.traction) / s.traction, 2);
    fit.rms_relative_residual = std::sqrt(squares / samples.size());
    return fit;
  }

  AsymptoticFit
  two_term_fit(const std::vector<RadialSample> &all_samples,
               const double                     lambda2)
  {
    const std::vector<RadialSample> samples = positive(all_samples);
    if (samples.size() < 3 || !(lambda2 > 0.02))
      {
        AsymptoticFit fit;
        fit.n_samples = samples.size();
        return fit;
      }
    constexpr double step = 1e-3;
    AsymptoticFit    best = project(samples, 0.01, lambda2);
    for (double lambda1 = 0.01 + step; lambda1 < lambda2 - 0.01;
         lambda1 += step)
      {
        const AsymptoticFit trial = project(samples, lambda1, lambda2);
        if (trial.rms_relative_residual < best.rms_relative_residual)
          best = trial;
      }
    // Golden section on the bracket around the best scan point.
    double low = best.lambda1 - step, high = best.lambda1 + step;
    const double ratio = (std::sqrt(5.) - 1.) / 2.;
    for (int iteration = 0; iteration < 60; ++iteration)
      {
        const double left  = high - ratio * (high - low);
        const double right = low + ratio * (high - low);
        if (project(samples, left, lambda2).rms_relative_residual <
            project(samples, right, lambda2).rms_relative_residual)
          high = right;
        else
          low = left;
      }
    const AsymptoticFit refined =
      project(samples, 0.5 * (low + high), lambda2);
    return refined.rms_relative_residual <= best.rms_relative_residual ?
             refined :
             best;
  }

  double
  one_term_validity_distance(const AsymptoticFit &fit, const double relative)
  {
    if (fit.k2 == 0. || fit.k1 == 0.)
      return std::numeric_limits<double>::infinity();
    return std::pow(relative / std::abs(fit.k2 / fit.k1),
                    1. / (fit.lambda2 - fit.lambda1));
  }
} // namespace FloorBlock::Analytic
