#pragma once

#include <contact/active_set.h>
#include <contact/forcing_term.h>

#include <cstdint>
#include <functional>
#include <string>

namespace FloorBlock::Contact
{
  /** @brief Plain settings of the semi-smooth Newton iteration. */
  struct NewtonSettings
  {
    /**
     * Converged when the l2 norm of the condensed residual (N) is below
     * this fraction of the reference force (the larger of the applied
     * load norm and the first residual of the increment) and the
     * open/stick/slip set did not change in the last step, or the set
     * changed but the residual is also at its round-off floor: the pairs
     * that change then sit on a kink of their law, where either state
     * gives the same residual and round-off picks one.
     */
    double relative_tolerance = 1e-10;
    /** Newton iterations allowed per solve. */
    unsigned int max_iterations = 50;
    /** Backtracking halvings tried before a full step is forced. */
    unsigned int max_line_search_steps = 6;
    /** Step length factor per backtracking step (-). */
    double line_search_reduction = 0.5;
    /** Armijo constant: accept if |R| <= (1 - c step)|R0| (-). */
    double sufficient_decrease = 1e-4;
    /**
     * The round-off floor (NewtonCallbacks::round_off_floor) may relax the
     * relative tolerance by at most this factor. It is a relief for a
     * tolerance just out of double precision's reach, not a licence to
     * stop anywhere: a wild iterate (kn = 1e14 Pa/m) has a huge |K||u|,
     * and without this cap stopped "converged" with a 72 % force
     * imbalance.
     */
    double max_round_off_relief = 1e3;
    /** A set revisited this often (not consecutively) counts as cycling. */
    unsigned int cycling_limit = 3;
    /** How tightly each update is solved by an iterative linear solver. */
    ForcingSettings forcing;
  };

  /** @brief What the physics reports about the current iterate. */
  struct NewtonIterate
  {
    /** l2 norm of the condensed residual (N). */
    double residual_norm = 0.;
    /** Hash of the open/stick/slip set. */
    std::uint64_t set_signature = 0;
    StateCounts   counts;
  };

  /**
   * @brief The physics as seen by the Newton driver (Lethe-style
   * callbacks): the driver never touches matrices or vectors.
   */
  struct NewtonCallbacks
  {
    /** Assemble matrix and residual at the current iterate. */
    std::function<NewtonIterate()> assemble;
    /**
     * Solve for the Newton update; false (with a message) on failure. The
     * first argument is the forcing term (forcing_term()): the relative
     * residual reduction an iterative solver needs; direct solvers ignore
     * it, and no solver needs to go below its own tolerance.
     */
    std::function<bool(double forcing, std::string &message)> solve_update;
    /** Set iterate = iterate at the last solve + step * update. */
    std::function<void(double step)> set_step;
    /**
     * Optional: the residual norm (N) that round-off alone can produce at
     * the iterate last assembled (e.g. a multiple of eps |K| |u|). A
     * stable set with a residual at or below it has converged as far as
     * double precision allows, even if the relative tolerance asks for
     * more. Asked for only when that decides the stop (a stable set
     * within NewtonSettings::max_round_off_relief of the tolerance): it
     * costs a product with |K|, as much as the residual itself.
     */
    std::function<double()> round_off_floor;
  };

  /** @brief Outcome of one Newton solve. */
  struct NewtonReport
  {
    bool         converged    = false;
    unsigned int n_iterations = 0;
    /** Final residual over the reference force (-). */
    double relative_residual = 0.;
    /** Counts of the last evaluated iterate (converged or not). */
    StateCounts counts;
    /** Why it failed; empty on success. */
    std::string failure_reason;
    /** Converged on the round-off floor, not on the relative tolerance. */
    bool stopped_at_round_off_floor = false;
  };

  /** What the relative stop test divides by. */
  enum class ReferenceForce
  {
    /** The larger of the given force and the first residual. */
    given_or_first_residual,
    /**
     * The given force alone: the caller already took the first residual
     * of another start into account (the increment predictor: a start
     * nearer the answer must not loosen or tighten the stop test).
     */
    given
  };

  /**
   * @brief Semi-smooth Newton with backtracking line search on the
   * residual norm and a guard against active-set cycling.
   *
   * @param[in] settings Iteration controls.
   * @param[in] reference_force Norm of the applied load vector (N), or
   *   the whole reference force, see @p reference.
   * @param[in] callbacks The physics.
   * @param[in] reference How the reference force is formed.
   */
  NewtonReport
  solve_newton(
    const NewtonSettings  &settings,
    const double           reference_force,
    const NewtonCallbacks &callbacks,
    const ReferenceForce   reference = ReferenceForce::given_or_first_residual);
} // namespace FloorBlock::Contact
