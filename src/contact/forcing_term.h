#pragma once

namespace FloorBlock::Contact
{
  /** @brief Controls of the inexact-Newton forcing term (Eisenstat-Walker). */
  struct ForcingSettings
  {
    /**
     * Largest forcing term (-): any solve after a step that barely
     * reduced the residual (an active-set change) asks for at least this
     * residual reduction. 1e-2
     * rather than Eisenstat and Walker's 0.9: a semi-smooth Newton step
     * decides the next open/stick/slip set from the update, and a loose
     * update sends it to a wrong set it then has to leave again.
     */
    double maximum = 1e-2;
    /**
     * Forcing term of the first solve of a load state (-). That update
     * carries the whole new load or support motion into the bodies, and
     * the first open/stick/slip set follows from it; a loose first update
     * misplaces that set by the linear error, a 1e-2 of the load step's
     * residual. Measured on the 3D plane-strain scene at 98k DoFs: with
     * the first solve at 1e-2 the first uplift increment reached an
     * iterate whose Newton matrix GMRES could not solve (a block held by
     * slipping pairs alone) and was cut back four times (89 Newton
     * iterations, 304 s); at 1e-8 no cutback (60 iterations, 173 s).
     * Where nothing goes wrong it costs little: 29k DoFs 54 Newton
     * iterations and 29.9 s against 66 and 29.2 s (whole solve).
     */
    double first = 1e-8;
    /** Eisenstat-Walker "choice 2" constants gamma and alpha (-). */
    double gamma = 0.9;
    double alpha = 2.;
  };

  /**
   * @brief Relative residual reduction (the forcing term eta) that the
   * next linear solve of an inexact Newton iteration needs.
   *
   * Newton's update only has to solve J du = -R well enough that the
   * linear error stays below the part of the residual that the
   * linearisation itself leaves: far from the answer that is a loose
   * solve, close to it (quadratic convergence) a tight one. Eisenstat and
   * Walker (SIAM J. Sci. Comput. 17, 1996, choice 2):
   * eta_k = gamma (|R_k| / |R_{k-1}|)^alpha, kept from dropping faster
   * than gamma eta_{k-1}^alpha while that exceeds 0.1, capped at
   * ForcingSettings::maximum. Two more bounds: never tighter than is
   * needed to reach the Newton stop (half the stop residual: the linear
   * error then cannot keep the next iterate above it). The linear solver
   * applies its own floor (LinearSolverSettings::relative_tolerance), and
   * direct solvers ignore the term.
   *
   * @param[in] settings The constants.
   * @param[in] residual Residual norm at the current iterate |R_k| (N).
   * @param[in] previous_residual |R_{k-1}| (N); zero or negative on the
   *   first iteration of a load state (then eta = ForcingSettings::first).
   * @param[in] previous_forcing eta_{k-1}; ignored on the first iteration.
   * @param[in] stop_residual Residual norm at which Newton stops (N).
   * @return eta_k in (0, maximum].
   */
  double
  forcing_term(const ForcingSettings &settings,
               double                 residual,
               double                 previous_residual,
               double                 previous_forcing,
               double                 stop_residual);
} // namespace FloorBlock::Contact
