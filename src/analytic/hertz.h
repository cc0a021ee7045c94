#pragma once

#include <analytic/status.h>

namespace FloorBlock::Analytic
{
  /** @brief Hertz contact of a cylinder on a flat: size and peak. */
  struct HertzLineContact
  {
    Status status = Status::ok;
    /** a, half-width of the contact strip (m), Johnson (1985) eq. 4.43. */
    double half_width = 0.;
    /** p0, largest contact pressure, at the centre line (Pa), eq. 4.45. */
    double peak_pressure = 0.;
  };

  /**
   * @brief Hertz line contact: a cylinder pressed on a flat by a load per
   * unit length, plane strain, frictionless (K. L. Johnson, Contact
   * Mechanics, Cambridge University Press 1985, section 4.3, eqs. 4.43 and
   * 4.45).
   *
   * The pressure is elliptic, \f$p(x) = p_0\sqrt{1 - x^2/a^2}\f$, with
   * \f[ a = \sqrt{\frac{4 P R}{\pi E^*}},\qquad p_0 = \frac{2P}{\pi a}, \f]
   * so that \f$\int_{-a}^{a} p\,dx = \pi a p_0/2 = P\f$. The contact
   * modulus is \f$1/E^* = (1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2\f$; on a rigid
   * flat \f$E^* = E/(1-\nu^2)\f$, the plane-strain modulus of the cylinder.
   *
   * Valid while the contact is small against the cylinder (a << R: each
   * body is an elastic half-space) and strains stay small and elastic.
   *
   * @param[in] line_load P, load per unit length of the cylinder (N/m), > 0.
   * @param[in] radius R, cylinder radius (m), > 0 (for two cylinders the
   * relative radius \f$1/R = 1/R_1 + 1/R_2\f$).
   * @param[in] contact_modulus E*, contact modulus (Pa), > 0.
   * @return a and p0; status invalid_input (both zero) for a non-finite or
   * non-positive input or an overflowing result.
   */
  HertzLineContact
  hertz_line_contact(const double line_load,
                     const double radius,
                     const double contact_modulus);

  /** @brief In-plane stresses on the axis of a Hertz line contact (Pa,
   * compression negative). */
  struct HertzAxisStress
  {
    double along_surface = 0.; ///< sigma_x, parallel to the surface
    double into_body     = 0.; ///< sigma_z, normal to the surface
  };

  /**
   * @brief The stresses at depth z below the centre of a Hertz line
   * contact (Johnson 1985, eq. 4.75, frictionless):
   * \f[ \sigma_x = -\frac{p_0}{a}\left(\frac{a^2 + 2z^2}{\sqrt{a^2+z^2}}
   *     - 2z\right),\qquad \sigma_z = -\frac{p_0\,a}{\sqrt{a^2+z^2}}; \f]
   * both are principal stresses there (no shear on the axis). At z = 0 both
   * equal -p0; sigma_x decays faster, so their difference peaks at z = 0.78a.
   * @param[in] peak_pressure p0 (Pa); half_width a (m), > 0; depth z (m), >= 0.
   */
  HertzAxisStress
  hertz_axis_stress(double peak_pressure, double half_width, double depth);
} // namespace FloorBlock::Analytic
