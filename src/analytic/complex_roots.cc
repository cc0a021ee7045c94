#include <analytic/complex_roots.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Analytic
{
  namespace
  {
    using Complex = std::complex<double>;

    /** Keeps @p root unless one within @p distance is there already. */
    void
    add_distinct(std::vector<Complex> &roots,
                 const Complex         root,
                 const double          distance)
    {
      for (const Complex &known : roots)
        if (std::abs(known - root) < distance)
          return;
      roots.push_back(root);
    }

    /** Bisection of a sign change of Re f on [a, b] of the real axis. */
    double
    bisect(const std::function<Complex(Complex)> &f, double a, double b)
    {
      double fa = f(a).real();
      for (int iteration = 0; iteration < 200 && b - a > 1e-15 * b; ++iteration)
        {
          const double middle = 0.5 * (a + b);
          const double fm     = f(middle).real();
          if ((fm < 0.) == (fa < 0.))
            {
              a  = middle;
              fa = fm;
            }
          else
            b = middle;
        }
      return 0.5 * (a + b);
    }

    /**
     * Secant iteration from z0, z1; the converged point, or NaN when it
     * left the search region, stalled or ended where |f| is not small.
     */
    Complex
    secant(const std::function<Complex(Complex)> &f,
           Complex                                z0,
           Complex                                z1,
           const RootSearch                      &search)
    {
      const Complex nan(std::nan(""), std::nan(""));
      Complex       f0 = f(z0), f1 = f(z1);
      const double  start_size = std::max(std::abs(f0), std::abs(f1));
      for (int iteration = 0; iteration < 100; ++iteration)
        {
          const Complex difference = f1 - f0;
          if (std::abs(difference) == 0.)
            break;
          const Complex z2 = z1 - f1 * (z1 - z0) / difference;
          if (!std::isfinite(z2.real()) || !std::isfinite(z2.imag()) ||
              std::abs(z2) > 10. * (search.largest_real_part +
                                    search.largest_imaginary_part))
            return nan;
          z0 = z1;
          f0 = f1;
          z1 = z2;
          f1 = f(z1);
          if (std::abs(z1 - z0) < 1e-14 * std::max(1., std::abs(z1)))
            return std::abs(f1) <= 1e-9 * start_size ? z1 : nan;
        }
      return nan;
    }
  } // namespace

  std::vector<std::complex<double>>
  complex_roots(const std::function<Complex(Complex)> &f,
                const RootSearch                      &search)
  {
    std::vector<Complex> roots;
    const double         low  = search.smallest_real_part;
    const double         high = search.largest_real_part;

    const unsigned int n          = search.n_real_samples;
    double             previous_x = low + (high - low) / n;
    double             previous   = f(previous_x).real();
    for (unsigned int k = 2; k <= n; ++k)
      {
        const double x     = low + (high - low) * k / n;
        const double value = f(x).real();
        if (value == 0.)
          add_distinct(roots, x, search.same_root_distance);
        else if ((value < 0.) != (previous < 0.) && previous != 0.)
          add_distinct(roots,
                       bisect(f, previous_x, x),
                       search.same_root_distance);
        previous_x = x;
        previous   = value;
      }

    const double step = 1. / search.starts_per_unit;
    for (double im = 0.5 * step; im <= search.largest_imaginary_part;
         im += step)
      for (double re = low + 0.5 * step; re <= high; re += step)
        {
          const Complex start(re, im);
          const Complex root =
            secant(f, start, start + Complex(0.25 * step, 0.1 * step), search);
          if (std::isnan(root.real()))
            continue;
          // Conjugate pairs: keep the upper one; |Im| tiny is real.
          Complex kept(root.real(), std::abs(root.imag()));
          if (kept.imag() < 1e-9 * std::max(1., std::abs(kept.real())))
            kept = kept.real();
          if (kept.real() > low && kept.real() <= high &&
              kept.imag() <= search.largest_imaginary_part)
            add_distinct(roots, kept, search.same_root_distance);
        }

    std::sort(roots.begin(),
              roots.end(),
              [](const Complex &a, const Complex &b) {
                return a.real() != b.real() ? a.real() < b.real() :
                                              a.imag() < b.imag();
              });
    return roots;
  }
} // namespace FloorBlock::Analytic
