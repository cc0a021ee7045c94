#pragma once

#include <analytic/status.h>

namespace FloorBlock::Analytic
{
  /** @brief Contact between two block corners at floor level. */
  struct CornerContact
  {
    Status status = Status::ok;
    /** A, contact area over the support width b (m^2), eq. 6.51. */
    double contact_area = 0.;
    /** c = A / b, contact length down the joint from floor level (m). */
    double contact_length = 0.;
    /** sigma_avg = Q / A (Pa), eq. 6.52. */
    double average_stress = 0.;
    /** sigma_max = 2 sigma_avg at floor level (Pa), eq. 6.53. */
    double max_stress = 0.;
  };

  /**
   * @brief Corner contact area and stress, eqs. 6.51-6.53.
   *
   * Compatibility assumption (derivation in README.md): the two faces of a
   * joint rotate against each other by \f$\theta\f$ with
   * \f$y = L\tan\theta\f$; over the contact length c the faces overlap by
   * \f$\delta(z) = \theta(c - z)\f$ (z down from floor level) and each fibre
   * of the block, of length L, shortens elastically,
   * \f$\sigma(z) = E\delta(z)/L\f$. The triangular stress carries
   * \f$Q = \sigma_{max} c b/2\f$, which gives
   * \f[ A = b c = \sqrt{\frac{2 b L^2 Q}{y E}},\quad
   *     \sigma_{avg} = \frac{Q}{A} = \sqrt{\frac{y E Q}{2 b L^2}},\quad
   *     \sigma_{max} = 2\sigma_{avg}. \f]
   * Q here is the force over the width b (N), not per metre: pass
   * (Q per metre) * b.
   *
   * @param[in] lateral_force_over_width Q over the support width b (N), >= 0.
   * @param[in] floor_lift y (m), see joint_floor_lift().
   * @param[in] youngs_modulus E (Pa), > 0.
   * @param[in] support_width b (m), > 0.
   * @param[in] block_width L (m), > 0.
   * @param[in] block_height H (m), > 0: the contact must fit on the joint.
   * @return A, c, sigma_avg, sigma_max. With y* = 2 Q L^2 / (E b H^2), the
   * lift at which the triangle's c reaches H: for y > y* the printed
   * 6.51-6.53 (ok); for |y| <= y* the whole joint face is in contact
   * (whole_joint_in_contact): the same compatibility with a uniform
   * closure added, A = b H, sigma_avg = Q / (b H), sigma_max = sigma_avg +
   * E |y| H / (2 L^2) (at floor level for y > 0, at the foot for y < 0),
   * continuous with 6.53 at y = y*; for y < -y* the joint closes at its
   * foot and not at floor level (zero_floor_lift, all zero), as for Q = 0
   * with y <= 0. invalid_input (all zero) for other bad inputs. Q = 0 with
   * y > 0 gives zeros, ok.
   */
  CornerContact
  corner_contact(const double lateral_force_over_width,
                 const double floor_lift,
                 const double youngs_modulus,
                 const double support_width,
                 const double block_width,
                 const double block_height);
} // namespace FloorBlock::Analytic
