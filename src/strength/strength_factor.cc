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
    const double radius = std::hypot(0.5 * (stress.xx - stress.yy), stress.xy);
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
    // The unstressed state lies inside (excess -sigma_ci s^a), and the
    // path k -> k (sigma_1, sigma_3) crosses the envelope at most once:
    // for sigma_3 >= 0 the excess k (sigma_1 - sigma_3) - sigma_ci (s +
    // m_b k sigma_3 / sigma_ci)^a is convex in k (a < 1) and negative at
    // k = 0, so once outside it stays outside; for sigma_3 < 0 it grows
    // with k (and beyond the tensile cut-off it is k (sigma_1 - sigma_3)
    // >= 0). So "outside" is monotone in k and bisection finds the one
    // crossing: on log k between the bounds (each halving a constant
    // relative step), below the smallest bound linearly from 0.
    constexpr double smallest_factor = 1e-4;
    double           inside = 0., outside = smallest_factor;
    if (excess(smallest_factor) < 0.)
      {
        if (excess(largest_strength_factor) < 0.)
          return largest_strength_factor;
        inside  = smallest_factor;
        outside = largest_strength_factor;
        // 60 halvings of ln(1e6) = 13.8: 1e-17, below a double's ulp.
        for (unsigned int halving = 0; halving < 60; ++halving)
          {
            const double middle = std::sqrt(inside * outside);
            (excess(middle) < 0. ? inside : outside) = middle;
          }
      }
    else
      for (unsigned int halving = 0; halving < 60; ++halving)
        {
          const double middle                      = 0.5 * (inside + outside);
          (excess(middle) < 0. ? inside : outside) = middle;
        }
    return std::min(0.5 * (inside + outside), largest_strength_factor);
  }
} // namespace FloorBlock::Strength
