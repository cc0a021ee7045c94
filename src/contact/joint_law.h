#pragma once

#include <deal.II/base/tensor.h>

#include <cstdint>

namespace FloorBlock::Contact
{
  /** Contact state of one joint node pair. */
  enum class JointState : std::uint8_t
  {
    open,  ///< separated (or tension beyond the tensile strength)
    stick, ///< closed, no slip in this increment
    slip   ///< closed, shear at the Coulomb limit
  };

  /** @brief "open", "stick" or "slip": the state's name in every output. */
  const char *
  state_name(const JointState state);

  /** @brief Material constants of a joint (SI units). */
  struct JointConstants
  {
    /** Normal stiffness kn (Pa/m) of the compliant law's springs. */
    double normal_stiffness = 0.;
    /** Shear stiffness ks (Pa/m) of the compliant law's springs. */
    double shear_stiffness = 0.;
    /** Friction angle (rad). */
    double friction_angle = 0.;
    /** Cohesion (Pa), lost once the pair slips or opens. */
    double cohesion = 0.;
    /** Tensile strength (Pa), lost once the pair slips or opens. */
    double tensile_strength = 0.;
  };

  /**
   * @brief History and multipliers a pair carries into an evaluation.
   *
   * Compliant law: normal_base = 0 (the normal spring has no memory),
   * tangential_base = shear traction at the last converged increment. The
   * exact (rigid) law keeps its multipliers in ExactContact and reads only
   * reference_slip and intact here; normal_base is a pre-stress of the
   * spring that no solver sets (the joint-report tests use it to build
   * responses with a traction at zero gap).
   */
  template <int dim>
  struct JointHistory
  {
    /** Normal traction before the penalty term (Pa, compression > 0). */
    double normal_base = 0.;
    /** Tangential traction before the penalty term (Pa). */
    dealii::Tensor<1, dim> tangential_base;
    /** Tangential relative displacement at the last converged state (m). */
    dealii::Tensor<1, dim> reference_slip;
    /** Cohesion and tensile strength still available. */
    bool intact = true;
  };

  /** @brief Result of one evaluation of the joint law. */
  template <int dim>
  struct JointResponse
  {
    JointState state = JointState::open;
    /** Normal traction (Pa), compression positive. */
    double normal_traction = 0.;
    /** Tangential traction (Pa), resisting the relative slip. */
    dealii::Tensor<1, dim> tangential_traction;
    /**
     * Internal force density on side B, \f$-t_n n + t_t\f$ (Pa); side A
     * receives the opposite.
     */
    dealii::Tensor<1, dim> force_density;
    /** Consistent tangent d(force_density)/d(jump) (Pa/m). */
    dealii::Tensor<2, dim> tangent;
    /**
     * Closed pair: the normal stiffness that scales its contact indicator
     * (Pa/m), kn for the compliant law, the surface stiffness E / h for
     * the exact law; 0 when open.
     */
    double closure_stiffness = 0.;
    /**
     * The traction is an exact-contact multiplier (rigid law): at the end
     * of a closed zone it falls like the square root of the distance to
     * the end, not linearly as a spring's (make_joint_reports()).
     */
    bool exact_traction = false;
    /** Normal gap (m), negative = overlap. */
    double gap = 0.;
    /** Tangential relative displacement (m). */
    dealii::Tensor<1, dim> slip;
  };

  /**
   * @brief Coulomb joint with elastic normal and shear springs and a
   * return mapping: the UDEC joint of the chapter's Table 6.1; also the
   * springs of the exact law's penalty start and crosspoints
   * (ContactSolver).
   *
   * With jump \f$[u] = u_B - u_A + g_0 n\f$, gap \f$g = [u]\cdot n\f$,
   * slip \f$s = [u] - g n\f$:
   * \f$t_n = \lambda_n - k_n g\f$; closed iff \f$t_n \ge -T\f$ (open
   * pairs carry nothing); trial \f$t_t^{tr} = \lambda_t + k_s (s -
   * s_{ref})\f$; stick iff \f$|t_t^{tr}| \le c + t_n\tan\phi\f$, otherwise
   * \f$t_t = (c + t_n\tan\phi)\, t_t^{tr}/|t_t^{tr}|\f$.
   *
   * The boundary case \f$t_n = 0\f$ counts as closed and stuck, which
   * gives blocks that are held only by contact a regular first tangent.
   */
  template <int dim>
  class CoulombJoint
  {
  public:
    explicit CoulombJoint(const JointConstants &parameters);

    /**
     * @param[in] jump Relative displacement B minus A plus initial gap
     *   times the normal (m).
     * @param[in] normal Unit normal from side A to side B.
     * @param[in] history Multipliers and converged history.
     */
    JointResponse<dim>
    evaluate(const dealii::Tensor<1, dim> &jump,
             const dealii::Tensor<1, dim> &normal,
             const JointHistory<dim>      &history) const;

    const JointConstants &
    parameters() const;

  private:
    const JointConstants constants;
  };
} // namespace FloorBlock::Contact
