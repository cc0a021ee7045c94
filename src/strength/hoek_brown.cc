#include <common/input_error.h>
#include <strength/hoek_brown.h>

#include <cmath>
#include <string>

namespace FloorBlock::Strength
{
  namespace
  {
    void
    require_within(const double       value,
                   const double       lowest,
                   const double       highest,
                   const std::string &name)
    {
      if (!(value >= lowest && value <= highest))
        throw InputError(name,
                         std::to_string(value),
                         "between " + std::to_string(lowest) + " and " +
                           std::to_string(highest));
    }
  } // namespace

  HoekBrownConstants
  generalised_hoek_brown(const double m_i,
                         const double gsi,
                         const double disturbance)
  {
    if (!(m_i > 0.) || !std::isfinite(m_i))
      throw InputError("Strength/m_i", std::to_string(m_i), "above 0");
    require_within(gsi, 10., 100., "Strength/GSI");
    require_within(disturbance, 0., 1., "Strength/Disturbance");
    const double D = disturbance;
    HoekBrownConstants constants;
    constants.m_b = m_i * std::exp((gsi - 100.) / (28. - 14. * D));
    constants.s   = std::exp((gsi - 100.) / (9. - 3. * D));
    constants.a =
      0.5 + (std::exp(-gsi / 15.) - std::exp(-20. / 3.)) / 6.;
    return constants;
  }

  double
  major_principal_strength(const double              sigma_3,
                           const double              sigma_ci,
                           const HoekBrownConstants &constants)
  {
    const double base = constants.m_b * sigma_3 / sigma_ci + constants.s;
    if (base <= 0.)
      return sigma_3;
    return sigma_3 + sigma_ci * std::pow(base, constants.a);
  }

  double
  uniaxial_compressive_strength(const double              sigma_ci,
                                const HoekBrownConstants &constants)
  {
    return sigma_ci * std::pow(constants.s, constants.a);
  }

  double
  tensile_strength(const double sigma_ci, const HoekBrownConstants &constants)
  {
    return constants.s * sigma_ci / constants.m_b;
  }
} // namespace FloorBlock::Strength
