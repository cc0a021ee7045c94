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

  namespace
  {
    /** Beyond the envelope (> 0) or inside it (< 0): sigma_1 - sigma_1f. */
    double
    envelope_excess(const double              sigma_1,
                    const double              sigma_3,
                    const double              sigma_ci,
                    const HoekBrownConstants &constants)
    {
      return sigma_1 - major_principal_strength(sigma_3, sigma_ci, constants);
    }
  } // namespace

  double
  strength_factor(const PrincipalStresses  &stresses,
                  const double              sigma_ci,
                  const HoekBrownConstants &constants)
  {
    const auto excess = [&](const double k) {
      return envelope_excess(k * stresses.sigma_1,
                             k * stresses.sigma_3,
                             sigma_ci,
                             constants);
    };
    // The unstressed state lies inside (excess -sigma_ci s^a). The first
    // crossing, bracketed on a geometric scan of k (confinement can bend
    // the path back inside after a crossing), then bisected.
    constexpr unsigned int n_scan = 400;
    const double           ratio  = std::pow(largest_strength_factor / 1e-4,
                                    1. / n_scan);
    double inside = 0., outside = 1e-4;
    if (excess(outside) < 0.)
      {
        bool crossed = false;
        for (unsigned int step = 0; step < n_scan && !crossed; ++step)
          {
            inside  = outside;
            outside = inside * ratio;
            crossed = excess(outside) >= 0.;
          }
        if (!crossed)
          return largest_strength_factor;
      }
    for (unsigned int halving = 0; halving < 60; ++halving)
      {
        const double middle = 0.5 * (inside + outside);
        (excess(middle) < 0. ? inside : outside) = middle;
      }
    return std::min(0.5 * (inside + outside), largest_strength_factor);
  }
} // namespace FloorBlock::Strength
