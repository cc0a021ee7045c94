#include <analytic/williams_field.h>

namespace FloorBlock::Analytic
{
  using Complex = std::complex<double>;

  WilliamsRows
  williams_rows(const Complex        lambda,
                const double         theta,
                const WedgeMaterial &material)
  {
    const Complex p = lambda + 1., m = lambda - 1.;
    const Complex cp = std::cos(p * theta), sp = std::sin(p * theta);
    const Complex cm = std::cos(m * theta), sm = std::sin(m * theta);
    const double  kappa = material.kolosov();
    const double  two_g = 2. * material.shear_modulus;
    WilliamsRows  rows;
    rows.normal_stress        = {cp, sp, cm, sm};
    rows.shear_stress         = {-p * sp, p * cp, -m * sm, m * cm};
    rows.radial_displacement  = {-p * cp / two_g,
                                 -p * sp / two_g,
                                 (kappa - lambda) * cm / two_g,
                                 (kappa - lambda) * sm / two_g};
    rows.angular_displacement = {p * sp / two_g,
                                 -p * cp / two_g,
                                 (kappa + lambda) * sm / two_g,
                                 -(kappa + lambda) * cm / two_g};
    return rows;
  }

  std::pair<Complex, Complex>
  airy_angular(const std::vector<Complex> &coefficients,
               const unsigned int          block,
               const Complex               lambda,
               const double                theta,
               const WedgeMaterial        &material)
  {
    const WilliamsRows rows = williams_rows(lambda, theta, material);
    Complex            f = 0., derivative = 0.;
    for (unsigned int j = 0; j < 4; ++j)
      {
        f += rows.normal_stress[j] * coefficients[4 * block + j];
        derivative += rows.shear_stress[j] * coefficients[4 * block + j];
      }
    return {f, derivative};
  }
} // namespace FloorBlock::Analytic
