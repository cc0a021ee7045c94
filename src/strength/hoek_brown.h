#pragma once

namespace FloorBlock::Strength
{
  /**
   * @brief Constants of the generalised Hoek-Brown criterion for a rock
   * mass, compression positive:
   * \f[ \sigma_1 = \sigma_3 + \sigma_{ci}\left(m_b\frac{\sigma_3}{\sigma_{ci}}
   *     + s\right)^a. \f]
   */
  struct HoekBrownConstants
  {
    double m_b = 0.; ///< reduced material constant (-)
    double s   = 0.; ///< rock-mass constant, 1 for intact rock (-)
    double a   = 0.; ///< exponent, 1/2 for intact rock (-)
  };

  /**
   * @brief m_b, s and a from the intact rock's m_i, the Geological Strength
   * Index and the disturbance factor (Hoek, Carranza-Torres and Corkum,
   * "Hoek-Brown failure criterion - 2002 edition", Proc. NARMS-TAC 2002,
   * eqs. 2-4):
   * \f[ m_b = m_i e^{(GSI-100)/(28-14D)},\quad s = e^{(GSI-100)/(9-3D)},
   *     \quad a = \tfrac12 + \tfrac16\left(e^{-GSI/15} - e^{-20/3}\right). \f]
   * GSI = 100 gives intact rock: m_b = m_i, s = 1, a = 1/2 exactly
   * (e^{-100/15} = e^{-20/3}), whatever D.
   *
   * @param[in] m_i intact-rock constant (-), > 0.
   * @param[in] gsi Geological Strength Index (-), 10..100.
   * @param[in] disturbance D (-), 0..1.
   * Throws InputError outside these ranges.
   */
  HoekBrownConstants
  generalised_hoek_brown(double m_i, double gsi, double disturbance);

  /**
   * @brief The largest major principal stress the rock carries at minor
   * principal stress @p sigma_3 (Pa, compression positive): \f$\sigma_{1f}\f$
   * above, or, where \f$m_b\sigma_3/\sigma_{ci} + s < 0\f$ (tension beyond
   * the criterion's tensile strength), @p sigma_3 itself: no strength left.
   */
  double
  major_principal_strength(double                    sigma_3,
                           double                    sigma_ci,
                           const HoekBrownConstants &constants);

  /**
   * @brief The rock mass's uniaxial compressive strength
   * \f$\sigma_c = \sigma_{ci} s^a\f$ (Pa): \f$\sigma_{1f}(0)\f$, the strength
   * at a free surface such as the floor at a block corner.
   */
  double
  uniaxial_compressive_strength(double                    sigma_ci,
                                const HoekBrownConstants &constants);

  /**
   * @brief The criterion's tensile strength \f$\sigma_t = s\sigma_{ci}/m_b\f$
   * (Pa, positive), where \f$\sigma_{1f} = \sigma_3\f$ (Hoek et al. 2002,
   * eq. 8: equal biaxial tension). With s = 1, m_b = m_i: the intact
   * rock's \f$\sigma_{ci}/m_i\f$.
   */
  double
  tensile_strength(double sigma_ci, const HoekBrownConstants &constants);
} // namespace FloorBlock::Strength
