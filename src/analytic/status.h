#pragma once

#include <string>

namespace FloorBlock::Analytic
{
  /**
   * @brief Outcome of an analytic evaluation. Every function of this module
   * returns one of these instead of producing inf or NaN.
   *
   * Statuses other than `ok` fall into two groups (see each function):
   * - the formula has no finite answer (a denominator vanishes or changes
   *   sign): the result vectors are left empty;
   * - the answer is finite but the assumed mechanism is not admissible
   *   (a joint would open, friction would be exceeded, ...): the finite
   *   values are kept so that the caller can show them.
   */
  enum class Status
  {
    ok,
    /** Non-finite, negative or out-of-range input (see describe()). */
    invalid_input,
    /** Eq. 6.5/6.41: the friction cone locks; no finite thrust slides
     * the chain (1 - a c <= 0, or tan(phi_h) tan(phi_v) >= 1). */
    self_locking,
    /** Eq. 6.29/6.35: L - H tan(phi_h) <= 0; base friction alone holds
     * the block against tipping, the rotation mechanism cannot form. */
    rotation_denominator_nonpositive,
    /** Eq. 6.35/6.36: the joint shear V_i needed without vertical slip
     * exceeds Q_i tan(phi_v); use rotation_vertical_slip instead. */
    vertical_friction_exceeded,
    /** Some Q_i < 0: a vertical joint would have to carry tension. */
    joint_opens,
    /** Some N_i < 0: a block base would have to carry tension. */
    base_lifts_off,
    /** Eq. 6.39-6.46: the base normal force falls outside the base. */
    normal_force_outside_base,
    /** Eq. 6.51: the joint closes at its foot, not at floor level
     * (y < -y*), or carries nothing with y <= 0: no floor-level corner
     * contact. */
    zero_floor_lift,
    /** Eq. 6.51: |y| <= y*, the triangular contact would be at least as
     * long as the block: the whole joint face is in contact (trapezoidal
     * stress; corner_contact()). Its values are the model's answer. */
    whole_joint_in_contact
  };

  /** @brief Whether Eqs. 6.51-6.53 answer with numbers under @p status:
   * ok (triangular contact) or whole_joint_in_contact. */
  inline bool
  has_contact_values(const Status status)
  {
    return status == Status::ok || status == Status::whole_joint_in_contact;
  }

  /**
   * @brief Plain-words explanation of a status for the command line.
   * @param[in] status Any status value.
   * @return One English sentence, never empty.
   */
  std::string
  describe(const Status status);

  /** @brief Short machine name ("self_locking") for CSV/JSON output. */
  std::string
  to_string(const Status status);
} // namespace FloorBlock::Analytic
