#include <analytic/asymptotic_fit.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace FloorBlock::Analytic
{
  namespace
  {
    /**
     * The K's of the terms with exponents @p lambdas (least squares in
     * the relative residual) and the residual, for a given lambda1 =
     * lambdas[0]; lambda2 and K2 are the second term's (0 without one).
     */
    AsymptoticFit
    project(const std::vector<RadialSample> &samples,
            const std::vector<double>       &lambdas)
    {
      // Rows a_ij = r_i^(l_j - 1) / p_i; solve sum_j c_j a_ij ~ 1 by the
      // normal equations (at most 4 terms), Gaussian elimination with
      // partial pivoting.
      // Distances in units of the largest one: the columns r^(l_j - 1)
      // then stay within a few decades of each other, where in metres
      // (1e-6 to 1e-3 m) they span many more and the normal equations
      // lose the digits that tell nearby exponents apart.
      double scale = 0.;
      for (const RadialSample &s : samples)
        scale = std::max(scale, s.distance);
      const std::size_t                n = lambdas.size();
      std::vector<std::vector<double>> normal(n,
                                              std::vector<double>(n + 1, 0.));
      for (const RadialSample &s : samples)
        {
          std::vector<double> row(n);
          for (std::size_t j = 0; j < n; ++j)
            row[j] = std::pow(s.distance / scale, lambdas[j] - 1.) / s.traction;
          for (std::size_t j = 0; j < n; ++j)
            {
              for (std::size_t k = 0; k < n; ++k)
                normal[j][k] += row[j] * row[k];
              normal[j][n] += row[j];
            }
        }
      AsymptoticFit fit;
      fit.lambda1             = lambdas[0];
      fit.lambda2             = n > 1 ? lambdas[1] : 0.;
      fit.n_samples           = samples.size();
      double largest_diagonal = 0.;
      for (std::size_t j = 0; j < n; ++j)
        largest_diagonal = std::max(largest_diagonal, std::abs(normal[j][j]));
      for (std::size_t column = 0; column < n; ++column)
        {
          std::size_t pivot = column;
          for (std::size_t row = column + 1; row < n; ++row)
            if (std::abs(normal[row][column]) > std::abs(normal[pivot][column]))
              pivot = row;
          if (!(std::abs(normal[pivot][column]) > 1e-14 * largest_diagonal))
            {
              fit.rms_relative_residual =
                std::numeric_limits<double>::infinity();
              return fit;
            }
          std::swap(normal[pivot], normal[column]);
          for (std::size_t row = column + 1; row < n; ++row)
            {
              const double factor =
                normal[row][column] / normal[column][column];
              for (std::size_t k = column; k <= n; ++k)
                normal[row][k] -= factor * normal[column][k];
            }
        }
      std::vector<double> k(n);
      for (std::size_t j = n; j-- > 0;)
        {
          double value = normal[j][n];
          for (std::size_t m = j + 1; m < n; ++m)
            value -= normal[j][m] * k[m];
          k[j] = value / normal[j][j];
        }
      for (std::size_t j = 0; j < n; ++j)
        k[j] /= std::pow(scale, lambdas[j] - 1.); // back to metres
      fit.k1         = k[0];
      fit.k2         = n > 1 ? k[1] : 0.;
      double squares = 0.;
      for (const RadialSample &s : samples)
        {
          double model = 0.;
          for (std::size_t j = 0; j < n; ++j)
            model += k[j] * std::pow(s.distance, lambdas[j] - 1.);
          squares += std::pow((model - s.traction) / s.traction, 2);
        }
      fit.rms_relative_residual = std::sqrt(squares / samples.size());
      return fit;
    }

    AsymptoticFit
    project(const std::vector<RadialSample> &samples,
            const double                     lambda1,
            const std::vector<double>       &further)
    {
      std::vector<double> lambdas{lambda1};
      lambdas.insert(lambdas.end(), further.begin(), further.end());
      return project(samples, lambdas);
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
    fit.lambda1        = 1. + slope;
    fit.k1             = std::exp(mean_y - slope * mean_x);
    double squares     = 0.;
    for (const RadialSample &s : samples)
      squares += std::pow((fit.k1 * std::pow(s.distance, slope) - s.traction) /
                            s.traction,
                          2);
    fit.rms_relative_residual = std::sqrt(squares / samples.size());
    return fit;
  }

  AsymptoticFit
  expansion_fit(const std::vector<RadialSample> &all_samples,
                const std::vector<double>       &further,
                const double                     scan_from,
                const double                     scan_to)
  {
    const std::vector<RadialSample> samples = positive(all_samples);
    if (samples.size() < further.size() + 2 || !(scan_to > scan_from))
      {
        AsymptoticFit fit;
        fit.n_samples = samples.size();
        return fit;
      }
    constexpr double step = 1e-3;
    AsymptoticFit    best = project(samples, scan_from, further);
    for (double lambda1 = scan_from + step; lambda1 < scan_to; lambda1 += step)
      {
        const AsymptoticFit trial = project(samples, lambda1, further);
        if (trial.rms_relative_residual < best.rms_relative_residual)
          best = trial;
      }
    // Golden section on the bracket around the best scan point.
    double       low = best.lambda1 - step, high = best.lambda1 + step;
    const double ratio = (std::sqrt(5.) - 1.) / 2.;
    for (int iteration = 0; iteration < 60; ++iteration)
      {
        const double left  = high - ratio * (high - low);
        const double right = low + ratio * (high - low);
        if (project(samples, left, further).rms_relative_residual <
            project(samples, right, further).rms_relative_residual)
          high = right;
        else
          low = left;
      }
    const AsymptoticFit refined = project(samples, 0.5 * (low + high), further);
    return refined.rms_relative_residual <= best.rms_relative_residual ?
             refined :
             best;
  }

  AsymptoticFit
  fixed_exponent_fit(const std::vector<RadialSample> &samples,
                     const std::vector<double>       &lambdas)
  {
    const std::vector<RadialSample> kept = positive(samples);
    if (lambdas.empty() || kept.size() < lambdas.size())
      {
        AsymptoticFit fit;
        fit.n_samples             = kept.size();
        fit.rms_relative_residual = std::numeric_limits<double>::infinity();
        return fit;
      }
    return project(kept, lambdas);
  }

  AsymptoticFit
  two_term_fit(const std::vector<RadialSample> &samples, const double lambda2)
  {
    if (!(lambda2 > 0.02))
      {
        AsymptoticFit fit;
        fit.n_samples = positive(samples).size();
        return fit;
      }
    return expansion_fit(samples, {lambda2}, 0.01, lambda2 - 0.01);
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
