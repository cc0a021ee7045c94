#pragma once

#include <array>
#include <complex>
#include <utility>
#include <vector>

namespace FloorBlock::Analytic
{
  /**
   * @brief Plane-strain elastic material of a wedge (Pa, -).
   */
  struct WedgeMaterial
  {
    double shear_modulus  = 1.;
    double poissons_ratio = 0.3;
    /** Kolosov's constant of plane strain, 3 - 4 nu. */
    double
    kolosov() const
    {
      return 3. - 4. * poissons_ratio;
    }
  };

  /** Four complex entries acting on a wedge's (A, B, C, D). */
  using WilliamsRow = std::array<std::complex<double>, 4>;

  /**
   * @brief Angular rows of one wedge's Williams field at angle theta,
   * acting on (A, B, C, D) of the Airy function r^(lambda + 1) F(theta),
   * F = A cos((lambda + 1) theta) + B sin((lambda + 1) theta) +
   * C cos((lambda - 1) theta) + D sin((lambda - 1) theta)
   * (M. L. Williams, J. Appl. Mech. 19, 1952), radial powers dropped:
   *   sigma_tt = lambda (lambda + 1) F r^(lambda - 1),
   *   sigma_rt = -lambda F' r^(lambda - 1),
   *   2G u_r = r^lambda [-(lambda + 1)(A c+ + B s+) + (kappa - lambda)(C c- + D
   * s-)], 2G u_t = r^lambda [(lambda + 1)(A s+ - B c+) + (kappa + lambda)(C s-
   * - D c-)], c+- = cos((lambda +- 1) theta), s+- = sin(...), kappa = 3 - 4 nu
   * (plane strain; the r^(lambda+1) terms of Michell's solution, J. R. Barber,
   * Elasticity). The stress rows hold F and F' (the stresses divided by
   * lambda (lambda + 1) and -lambda), so that no row vanishes with lambda;
   * the displacement rows include 1/(2G). Unit-tested against Hooke's law.
   */
  struct WilliamsRows
  {
    WilliamsRow normal_stress;        ///< F
    WilliamsRow shear_stress;         ///< F'
    WilliamsRow radial_displacement;  ///< U_r = u_r / r^lambda
    WilliamsRow angular_displacement; ///< U_t = u_t / r^lambda
  };

  /** @brief The rows of WilliamsRows at @p theta (rad). */
  WilliamsRows
  williams_rows(std::complex<double> lambda,
                double               theta,
                const WedgeMaterial &material);

  /**
   * @brief F and F' at @p theta of the coefficients of wedge @p block in
   * @p coefficients (A, B, C, D of wedge 0, then of wedge 1, ...).
   */
  std::pair<std::complex<double>, std::complex<double>>
  airy_angular(const std::vector<std::complex<double>> &coefficients,
               unsigned int                             block,
               std::complex<double>                     lambda,
               double                                   theta,
               const WedgeMaterial                     &material);
} // namespace FloorBlock::Analytic
