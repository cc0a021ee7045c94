#include <strength/strength_factor.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Strength
{
  PlaneStrainStress
  operator+(const PlaneStrainStress &a, const PlaneStrainStress &b)
  {
    return {a.xx + b.xx, a.yy + b.yy, a.xy + b.xy, a.zz + b.zz};
  }

  PlaneStrainStress
  operator*(const double factor, const PlaneStrainStress &stress)
  {
    return {factor * stress.xx,
            factor * stress.yy,
            factor * stress.xy,
            factor * stress.zz};
  }

  PrincipalStresses
  principal_stresses(const PlaneStrainStress &stress)
  {
    const double centre = 0.5 * (stress.xx + stress.yy);
    const double radius =
      std::hypot(0.5 * (stress.xx - stress.yy), stress.xy);
    // Tension positive here; flipped on return.
    const double largest  = std::max(centre + radius, stress.zz);
    const double smallest = std::min(centre - radius, stress.zz);
    return {-smallest, -largest};
  }

  double
  strength_factor(const PrincipalStresses  &stresses,
                  const double              sigma_ci,
                  const HoekBrownConstants &constants)
  {
    const double tension_limit = tensile_strength(sigma_ci, constants);
    double       factor        = largest_strength_factor;
    if (stresses.sigma_1 > 0. && stresses.sigma_3 > -tension_limit)
      factor = std::max(major_principal_strength(stresses.sigma_3,
                                                 sigma_ci,
                                                 constants),
                        0.) /
               stresses.sigma_1;
    else if (stresses.sigma_3 < 0.)
      factor = tension_limit / -stresses.sigma_3;
    return std::min(factor, largest_strength_factor);
  }
} // namespace FloorBlock::Strength
