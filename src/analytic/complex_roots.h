#pragma once

#include <complex>
#include <functional>
#include <vector>

namespace FloorBlock::Analytic
{
  /** @brief Where complex_roots() looks, and how closely. */
  struct RootSearch
  {
    double smallest_real_part     = 1e-3; ///< exclusive lower end of Re z
    double largest_real_part      = 2.;   ///< inclusive upper end of Re z
    double largest_imaginary_part = 1.;   ///< roots with 0 <= Im z <= this
    /** Real-axis samples for sign changes (the function is real there). */
    unsigned int n_real_samples = 4000;
    /** Secant starts per unit of Re z and of Im z off the real axis. */
    unsigned int starts_per_unit = 10;
    /** Roots closer than this count as one. */
    double same_root_distance = 1e-7;
  };

  /**
   * @brief Zeros of an analytic function that is real on the real axis
   * (so its complex zeros come in conjugate pairs; only Im z >= 0 are
   * returned), inside the strip of @p search, sorted by real part, then
   * imaginary part.
   *
   * Two passes, because neither alone is reliable: sign changes of f
   * along the real axis, refined by bisection (simple real zeros however
   * close together the samples resolve them), and secant iterations from
   * a grid of complex starts (complex zeros, and real double zeros that
   * touch the axis without a sign change). A secant result counts only if
   * it converged (step below 1e-14 |z|) to a point where |f| is below
   * 1e-9 of |f| at its start.
   */
  std::vector<std::complex<double>>
  complex_roots(
    const std::function<std::complex<double>(std::complex<double>)> &f,
    const RootSearch                                                &search);
} // namespace FloorBlock::Analytic
