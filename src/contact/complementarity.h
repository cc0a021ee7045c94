#pragma once

#include <contact/joint_law.h>

#include <deal.II/base/tensor.h>

namespace FloorBlock::Contact
{
  /**
   * @brief Constants of the exact (rigid) Coulomb contact law and of its
   * complementarity function (SI units).
   */
  struct ComplementarityParameters
  {
    /** Coulomb friction coefficient \f$\mu = \tan\phi\f$ (-), >= 0. */
    double friction_coefficient = 0.;
    /**
     * Cohesion \f$c\f$ (Pa), >= 0: shear strength at zero pressure of a
     * closed pair. Constant here; a caller that loses cohesion once a
     * pair slips or opens (UDEC, JointHistory::intact) passes 0 after
     * that.
     */
    double cohesion = 0.;
    /**
     * Normal complementarity parameter \f$c_n\f$ (Pa/m), > 0. Changes the
     * Newton iterates, never the converged answer; a natural scale is the
     * surface's own stiffness, Young's modulus / cell size.
     */
    double normal_parameter = 0.;
    /** Tangential complementarity parameter \f$c_t\f$ (Pa/m), > 0. */
    double tangential_parameter = 0.;
  };

  /**
   * @brief Generalized (Newton) derivatives of the complementarity
   * function at one node pair, for chaining with \f$\partial g/\partial
   * u\f$ and \f$\partial\Delta s/\partial u\f$.
   *
   * \f$C_n\f$ depends on \f$\lambda_n\f$ and \f$g\f$ only: its
   * derivatives by \f$\lambda_t\f$ and \f$\Delta s\f$ are identically
   * zero and not stored. Tensor<2> entries are [row of C_t][column of the
   * input].
   */
  template <int dim>
  struct ComplementarityDerivatives
  {
    /** \f$\partial C_n/\partial\lambda_n\f$ (-): 1 open, 0 closed. */
    double normal_by_normal_multiplier = 0.;
    /** \f$\partial C_n/\partial g\f$ (Pa/m): 0 open, \f$c_n\f$ closed. */
    double normal_by_gap = 0.;
    /** \f$\partial C_t/\partial\lambda_n\f$ (-). */
    dealii::Tensor<1, dim> tangential_by_normal_multiplier;
    /** \f$\partial C_t/\partial\lambda_t\f$ (-). */
    dealii::Tensor<2, dim> tangential_by_tangential_multiplier;
    /** \f$\partial C_t/\partial g\f$ (Pa/m). */
    dealii::Tensor<1, dim> tangential_by_gap;
    /** \f$\partial C_t/\partial\Delta s\f$ (Pa/m). */
    dealii::Tensor<2, dim> tangential_by_slip_increment;
  };

  /** @brief Value, state and derivatives at one node pair. */
  template <int dim>
  struct ComplementarityResponse
  {
    /** Open, stick or slip, decided by the augmented multipliers. */
    JointState state = JointState::open;
    /** \f$C_n\f$ (Pa); zero exactly where the normal conditions hold. */
    double normal_residual = 0.;
    /** \f$C_t\f$ (Pa); zero exactly where Coulomb's law holds. */
    dealii::Tensor<1, dim> tangential_residual;
    /** Generalized derivatives of \f$(C_n, C_t)\f$. */
    ComplementarityDerivatives<dim> derivatives;
  };

  /**
   * @brief Alart–Curnier complementarity function of unilateral contact
   * with Coulomb friction at one node pair: the exact (rigid) contact law
   * as a nonsmooth equation \f$C(\lambda, g, \Delta s) = 0\f$ for a
   * semismooth Newton method with the nodal multipliers as unknowns.
   *
   * References: P. Alart, A. Curnier, A mixed formulation for frictional
   * contact problems prone to Newton like solution methods, Comput.
   * Methods Appl. Mech. Engrg. 92 (1991) 353–375; S. Hüeber, G. Stadler,
   * B. Wohlmuth, A primal-dual active set algorithm for three-dimensional
   * contact problems with Coulomb friction, SIAM J. Sci. Comput. 30(2)
   * (2008) 572–596, whose tangential NCP function is
   * \f$\max(R, |\xi_t|)\, C_t\f$ with \f$C_t\f$ below (no division by
   * \f$|\xi_t|\f$; the same zeros and stick/slip sets where \f$R > 0\f$).
   *
   * <b>Conventions</b> (src/contact/README.md): pair = side A node + side
   * B node, normal \f$n\f$ from A to B, gap \f$g = [u]\cdot n\f$ (m,
   * positive open), \f$\Delta s\f$ = tangential slip of B relative to A
   * since the last converged state (m). The multiplier is the contact
   * traction on side A, \f$t_A = -\lambda_n n + \lambda_t\f$ (Pa); side B
   * receives \f$-t_A\f$, i.e. \f$-\lambda_n n + \lambda_t\f$ is the
   * internal force density on B of JointResponse::force_density. So
   * \f$\lambda_n > 0\f$ is compression, and at slip \f$\lambda_t\f$
   * points *along* \f$\Delta s\f$: the traction \f$-\lambda_t\f$ acting
   * on the moving side B resists its slip, and the dissipation
   * \f$\lambda_t\cdot\Delta s \ge 0\f$. Same sign as
   * JointResponse::tangential_traction.
   *
   * <b>Contact conditions</b> (\f$R\f$ = shear strength):
   * \f$g \ge 0,\ \lambda_n \ge 0,\ \lambda_n g = 0\f$;
   * open (\f$g > 0\f$): \f$\lambda_t = 0\f$;
   * closed: \f$|\lambda_t| \le c + \mu\lambda_n\f$, with
   * \f$\Delta s = 0\f$ (stick) or \f$\lambda_t = (c + \mu\lambda_n)\,
   * \Delta s/|\Delta s|\f$ (slip).
   *
   * <b>Function.</b> With the augmented multipliers
   * \f$\xi_n = \lambda_n - c_n g\f$, \f$\xi_t = \lambda_t + c_t\Delta
   * s\f$ and the radius \f$R = c + \mu\xi_n\f$ if \f$\xi_n \ge 0\f$,
   * else \f$R = 0\f$:
   * \f[ C_n = \lambda_n - \max(0, \xi_n), \qquad
   *     C_t = \lambda_t - P_{B(R)}(\xi_t), \f]
   * \f$P_{B(R)}\f$ the projection onto the disk (3D) or interval (2D) of
   * radius \f$R\f$. Branches:
   * - open, \f$\xi_n < 0\f$: \f$C_n = \lambda_n\f$, \f$C_t = \lambda_t\f$;
   * - closed, \f$\xi_n \ge 0\f$: \f$C_n = c_n g\f$, and
   *   - stick, \f$|\xi_t| \le R\f$: \f$C_t = \lambda_t - \xi_t = -c_t
   *     \Delta s\f$;
   *   - slip, \f$|\xi_t| > R\f$: \f$C_t = \lambda_t - R\, e\f$,
   *     \f$e = \xi_t/|\xi_t|\f$.
   *
   * \f$C = 0\f$ holds exactly at the solutions of the conditions above,
   * for every \f$c_n, c_t > 0\f$: \f$C_n = 0\f$ is \f$\lambda_n =
   * \max(0, \lambda_n - c_n g)\f$, the complementarity of \f$g\f$ and
   * \f$\lambda_n\f$; open needs \f$\lambda_t = 0\f$; stick needs
   * \f$\Delta s = 0\f$ and then \f$|\lambda_t| = |\xi_t| \le R\f$; slip
   * needs \f$\lambda_t = R\,e\f$, so \f$\xi_t = (R + c_t|\Delta s|)
   * \Delta s/|\Delta s|\f$ and \f$\lambda_t = R\,\Delta s/|\Delta s|\f$.
   * The parameters change the iterates, never the converged answer.
   *
   * <b>Derivatives</b> (every one not listed is 0):
   * - open: \f$\partial C_n/\partial\lambda_n = 1\f$,
   *   \f$\partial C_t/\partial\lambda_t = I\f$;
   * - closed: \f$\partial C_n/\partial g = c_n\f$, and
   *   - stick: \f$\partial C_t/\partial\Delta s = -c_t I\f$;
   *   - slip, with \f$\rho = R/|\xi_t| \in [0, 1)\f$ and
   *     \f$\partial e/\partial\xi_t = (I - e\otimes e)/|\xi_t|\f$:
   *     \f$\partial C_t/\partial\lambda_t = I - \rho(I - e\otimes e)\f$,
   *     \f$\partial C_t/\partial\Delta s = -c_t\rho(I - e\otimes e)\f$,
   *     \f$\partial C_t/\partial\lambda_n = -\mu e\f$ and
   *     \f$\partial C_t/\partial g = \mu c_n e\f$ (from
   *     \f$\partial R/\partial\lambda_n = \mu\f$, \f$\partial
   *     R/\partial g = -\mu c_n\f$).
   *
   * <b>Tangent plane.</b> \f$\lambda_t\f$ and \f$\Delta s\f$ are
   * Tensor<1, dim> in global coordinates and should lie in the tangent
   * plane; the function (and its derivatives, with the full identity
   * \f$I\f$) is that of the same formula on all of
   * \f$\mathbb{R}^{dim}\f$, whose value is tangent for tangent inputs.
   * The caller writes \f$\lambda_t = \sum_k \alpha_k\tau_k\f$ over a
   * tangent basis and uses the dim-1 equations \f$\tau_j\cdot C_t = 0\f$
   * (i.e. \f$\tau_j^T(\partial C_t/\partial\lambda_t)\tau_k\f$); the
   * normal component of \f$C_t\f$ must not be used as an equation (it is
   * empty in stick).
   *
   * <b>Choices at the kinks</b> (each an element of Clarke's generalized
   * Jacobian unless said otherwise):
   * - \f$\xi_n = 0\f$: closed (the \f$C_n = c_n g\f$ branch), as
   *   CoulombJoint counts \f$t_n = 0\f$ as closed: touching pairs start
   *   with a constraint, not free.
   * - \f$|\xi_t| = R\f$, including \f$\xi_t = 0 = R\f$ (the first iterate
   *   \f$\lambda = 0, g = 0, \Delta s = 0\f$): stick, so that blocks held
   *   only by contact get a regular first Newton matrix (as in
   *   CoulombJoint). For \f$\mu = c = 0\f$ (frictionless) the stick
   *   branch at \f$\xi_t = 0\f$ is not a generalized derivative (the
   *   function is \f$C_t = \lambda_t\f$ there) but has the same value;
   *   the next iterate has \f$\xi_t \ne 0\f$ and takes the slip branch.
   * - Cohesion: \f$R\f$ jumps from \f$c\f$ to 0 where \f$\xi_n\f$ changes
   *   sign, so for \f$c > 0\f$ the function is discontinuous there and
   *   has no generalized derivative; the closed branch's derivative is
   *   returned. This is the law, not the formula: a closed pair at zero
   *   pressure may carry \f$c\f$, an open one nothing. With \f$c = 0\f$
   *   (default) \f$C\f$ is Lipschitz and piecewise smooth, hence
   *   semismooth. (The radius \f$c + \mu\max(0, \xi_n)\f$ would wrongly
   *   bind open pairs by cohesion.)
   *
   * No tensile strength: a bonded pair that breaks at \f$\lambda_n = -T\f$
   * is no complementarity problem of this kind (and not monotone); the
   * exact law is unilateral.
   */
  template <int dim>
  class CoulombComplementarity
  {
  public:
    /**
     * @brief Checks and stores the constants.
     * @param[in] parameters friction coefficient >= 0, cohesion >= 0 (Pa),
     *   complementarity parameters > 0 (Pa/m); throws ExcMessage
     *   otherwise.
     */
    explicit CoulombComplementarity(
      const ComplementarityParameters &parameters);

    /**
     * @brief Evaluates \f$C\f$, the state and the generalized
     * derivatives at one node pair.
     * @param[in] normal_multiplier \f$\lambda_n\f$ (Pa), compression
     *   positive.
     * @param[in] tangential_multiplier \f$\lambda_t\f$ (Pa), tangent-plane
     *   vector, the tangential traction on side A (along the slip of B
     *   when slipping).
     * @param[in] gap \f$g\f$ (m), positive open.
     * @param[in] slip_increment \f$\Delta s\f$ (m), tangential slip of B
     *   relative to A since the last converged state.
     */
    ComplementarityResponse<dim>
    evaluate(const double                  normal_multiplier,
             const dealii::Tensor<1, dim> &tangential_multiplier,
             const double                  gap,
             const dealii::Tensor<1, dim> &slip_increment) const;

    /** @brief The constants given at construction. */
    const ComplementarityParameters &
    parameters() const;

  private:
    ComplementarityParameters constants;
  };
} // namespace FloorBlock::Contact
