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
   * strength over the stress, FS < 1 where the criterion is violated.
   *
   *  - Compression (\f$\sigma_1 > 0\f$, \f$\sigma_3\f$ above the tensile
   *    strength \f$-\sigma_t\f$): \f$FS = \sigma_{1f}(\sigma_3)/\sigma_1\f$,
   *    the strength at the acting confinement over the major principal
   *    compressive stress; 0 where \f$\sigma_{1f}(\sigma_3) \le 0\f$
   *    (confinement so tensile that no compression is carried).
   *  - Tension at or beyond \f$\sigma_t\f$, or no compression
   *    (\f$\sigma_1 \le 0\f$): \f$FS = \sigma_t/(-\sigma_3)\f$, the tensile
   *    strength over the largest tension.
   * Capped at largest_strength_factor (an unloaded point).
   */
  double
  strength_factor(const PrincipalStresses  &stresses,
                  double                    sigma_ci,
                  const HoekBrownConstants &constants);
} // namespace FloorBlock::Strength
