#pragma once

#include <strength/hoek_brown.h>

namespace FloorBlock::Strength
{
  /**
   * @brief A plane-strain stress state (Pa, tension positive as the FEM
   * computes it): the in-plane components and the out-of-plane normal
   * stress \f$\sigma_{zz} = \nu(\sigma_{xx} + \sigma_{yy})\f$.
   */
  struct PlaneStrainStress
  {
    double xx = 0.;
    double yy = 0.;
    double xy = 0.;
    double zz = 0.;
  };

  /** @brief Component-wise a + b, for averages along a path. */
  PlaneStrainStress
  operator+(const PlaneStrainStress &a, const PlaneStrainStress &b);

  /** @brief Component-wise factor * stress. */
  PlaneStrainStress
  operator*(double factor, const PlaneStrainStress &stress);

  /**
   * @brief Major and minor principal stresses, compression positive (Pa):
   * \f$\sigma_1 \ge \sigma_3\f$ among the two in-plane principal stresses
   * and \f$\sigma_{zz}\f$, each with its sign flipped.
   */
  struct PrincipalStresses
  {
    double sigma_1 = 0.;
    double sigma_3 = 0.;
  };

  PrincipalStresses
  principal_stresses(const PlaneStrainStress &stress);

  /** FS is written as at most this: a point that carries (almost) nothing
   * has a strength factor without bound. */
  constexpr double largest_strength_factor = 100.;

  /**
   * @brief Strength factor of the Hoek-Brown rock at one stress state: the
   * factor k by which the whole stress state can be scaled before it
   * reaches the envelope, \f$k\sigma_1 = \sigma_{1f}(k\sigma_3)\f$ (the
   * smallest such k > 0); FS < 1 where the criterion is violated.
   *
   * At a free surface (\f$\sigma_3 = 0\f$) k is the strength over the stress,
   * \f$\sigma_c/\sigma_1\f$, the chapter's route; in equal biaxial tension
   * it is \f$\sigma_t/|\sigma_3|\f$. Why not \f$\sigma_{1f}(\sigma_3)/
   * \sigma_1\f$ at the acting \f$\sigma_3\f$: that ratio falls to 0 as
   * \f$\sigma_3\f$ approaches the tensile strength \f$-\sigma_t\f$ (where
   * \f$\sigma_{1f} \to -\sigma_t\f$) and has no meaning beyond it, so near
   * the tension a change of \f$\sigma_3\f$ by 1 % of \f$\sigma_1\f$
   * moves it by a quarter; k is continuous there and of the same value at a
   * free surface. Capped at largest_strength_factor (an unloaded point, or
   * a state too confined to reach the envelope before the cap).
   */
  double
  strength_factor(const PrincipalStresses  &stresses,
                  double                    sigma_ci,
                  const HoekBrownConstants &constants);
} // namespace FloorBlock::Strength
