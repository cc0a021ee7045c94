#pragma once

namespace FloorBlock::Strength
{
  /**
   * @brief The joint data of the Barton-Bandis model, SI.
   *
   * The published relations are fitted in MPa, mm and degrees; the
   * functions below take and return SI values and convert at their edge.
   */
  struct BartonBandisJoint
  {
    double roughness_coefficient   = 0.; ///< JRC (-), 0..20
    double wall_strength           = 0.; ///< JCS (Pa), > 0
    double initial_aperture        = 0.; ///< a_j (m), > 0, unloaded joint
    double residual_friction_angle = 0.; ///< phi_r (rad)
  };

  /**
   * @brief Barton's estimate of the unloaded aperture (Barton, Bandis and
   * Bakhtar 1985): \f$a_j = \frac{JRC}{5}\left(0.2\frac{\sigma_c}{JCS} -
   * 0.1\right)\f$ mm, with sigma_c the intact rock's UCS. A fresh joint
   * (JCS = sigma_c) gets JRC/50 mm. Fitted for JRC 5-15, JCS 22-182 MPa
   * and apertures 0.1-0.6 mm.
   * @param[in] roughness_coefficient JRC (-).
   * @param[in] wall_strength JCS (Pa), > 0.
   * @param[in] intact_ucs sigma_c (Pa).
   * @return a_j (m); zero or negative where the relation has no answer
   *   (JRC = 0, or JCS >= 2 sigma_c).
   */
  double
  barton_initial_aperture(double roughness_coefficient,
                          double wall_strength,
                          double intact_ucs);

  /**
   * @brief Initial normal stiffness of a fresh joint, first loading cycle
   * (Bandis, Lumsden and Barton 1983): \f$K_{ni} = -7.15 + 1.75\,JRC +
   * 0.02\,JCS/a_j\f$ in MPa/mm, JCS in MPa and a_j in mm.
   * @return K_ni (Pa/m); not positive for smooth joints with wide
   *   apertures (the fit's range ends there).
   */
  double
  bandis_initial_normal_stiffness(const BartonBandisJoint &joint);

  /**
   * @brief Maximum closure of a fresh joint, first loading cycle (Bandis,
   * Lumsden and Barton 1983): \f$V_m = A + B\,JRC + C\,(JCS/a_j)^D\f$ mm
   * with A = -0.2960, B = -0.0056, C = 2.2410, D = -0.2450, JCS/a_j in
   * MPa/mm.
   * @return V_m (m); not positive for very high JCS/a_j.
   */
  double
  bandis_maximum_closure(const BartonBandisJoint &joint);

  /**
   * @brief The largest a_j with a positive bandis_initial_normal_stiffness()
   * (m); infinite where every aperture gives one (JRC > 4.09).
   * @param[in] wall_strength JCS (Pa).
   */
  double
  bandis_largest_aperture_for_stiffness(double roughness_coefficient,
                                        double wall_strength);

  /**
   * @brief The smallest a_j with a positive bandis_maximum_closure() (m).
   * @param[in] wall_strength JCS (Pa).
   */
  double
  bandis_smallest_aperture_for_closure(double roughness_coefficient,
                                       double wall_strength);

  /**
   * @brief Tangent normal stiffness of the Bandis hyperbola
   * \f$\sigma_n = \Delta V / (a - b\,\Delta V)\f$ (K_ni = 1/a, V_m = a/b)
   * at a normal stress: \f$K_n = K_{ni}\left(1 - \frac{\sigma_n}{V_m
   * K_{ni} + \sigma_n}\right)^{-2} = K_{ni}\left(1 + \frac{\sigma_n}{V_m
   * K_{ni}}\right)^2\f$ (Brady and Brown 2004, section 4.8.2).
   * @param[in] initial_normal_stiffness K_ni (Pa/m), > 0.
   * @param[in] maximum_closure V_m (m), > 0.
   * @param[in] normal_stress sigma_n (Pa), >= 0, compression positive.
   * @return K_n (Pa/m).
   */
  double
  hyperbolic_normal_stiffness(double initial_normal_stiffness,
                              double maximum_closure,
                              double normal_stress);

  /**
   * @brief Closure of the Bandis hyperbola at a normal stress:
   * \f$\Delta V = \sigma_n V_m / (K_{ni} V_m + \sigma_n)\f$ (m), below
   * V_m for every finite stress.
   */
  double
  hyperbolic_closure(double initial_normal_stiffness,
                     double maximum_closure,
                     double normal_stress);

  /**
   * @brief Barton's peak friction angle (Barton and Choubey 1977):
   * \f$\phi_{peak} = JRC \log_{10}(JCS/\sigma_n) + \phi_r\f$, the first
   * term in degrees. Used up to 70 degrees.
   * @param[in] normal_stress sigma_n (Pa), > 0.
   * @return phi_peak (rad).
   */
  double
  barton_peak_friction_angle(const BartonBandisJoint &joint,
                             double                   normal_stress);

  /**
   * @brief Peak shear stiffness (Barton 1982; Barton, Bandis and Bakhtar
   * 1985): the peak strength over a peak shear displacement of 1 % of
   * the sheared length, \f$K_s = \frac{100}{L_x}\,\sigma_n
   * \tan\phi_{peak}\f$. The 100 is 1/0.01 and carries no unit: MPa/m with
   * sigma_n in MPa, Pa/m with sigma_n in Pa.
   * @param[in] normal_stress sigma_n (Pa), > 0.
   * @param[in] sheared_length L_x (m), the joint's length along the shear.
   * @return K_s (Pa/m).
   */
  double
  barton_shear_stiffness(const BartonBandisJoint &joint,
                         double                   normal_stress,
                         double                   sheared_length);
} // namespace FloorBlock::Strength
