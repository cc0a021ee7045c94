#pragma once

#include <optional>

namespace FloorBlock::Studies
{
  /**
   * What the race needs to know of one FE degree's accuracy loop
   * (TargetLoop) between its steps.
   */
  struct RacerState
  {
    bool joined   = false; ///< the loop has been started
    bool finished = false; ///< met the target, or stopped without
    bool met      = false;
    /** At least one level was checked (the loop has an estimate). */
    bool checked = false;
    /** A checked pair met the target; the next level is to confirm it. */
    bool confirming = false;
    /**
     * Stopped by Mesh/Refinement time budget, which both loops share: the
     * race is over.
     */
    bool   out_of_time = false;
    double time_spent  = 0.; ///< s of the loop's own solves
    /** The reported solve's largest target-figure error; none yet. */
    std::optional<double> reported_error;
  };

  /** Whose step it is. */
  enum class RaceTurn
  {
    degree_1,
    degree_2,
    over
  };

  /**
   * @brief The next turn of Solver/FE degree = auto.
   *
   * Degree 1 starts. Degree 2 joins only once degree 1's level 0 was
   * checked without meeting the target (or degree 1 stopped): if degree
   * 1's level-0 pair meets, no degree-2 solve can meet sooner, because
   * degree 2 on the level-0 mesh has the DoFs of degree 1's check and
   * costs more per DoF (23956 DoFs on the default scene: 5.4 s against
   * 4.3 s), and its own check has four times as many. Then a loop whose
   * checked pair met the target steps next, to confirm it (the race may
   * be over after that step); otherwise the loop with less time spent (a
   * tie goes to degree 1), so neither gets more than one step ahead of
   * the other. The race is over when one meets the target or both have
   * stopped. With time alone deciding, a loop whose check met could wait
   * for its confirming level behind the other degree's far larger check
   * (on the exact law's default scene, degree 1's level 5 behind an
   * 880k-DoF degree-2 check); confirming first avoids that.
   */
  RaceTurn
  next_race_turn(const RacerState &degree_1, const RacerState &degree_2);

  /**
   * @brief The degree (1 or 2) whose solve is reported when the race is
   * over: the one that met the target; if neither did, the one with the
   * smaller reported error (a loop without an estimate counts as
   * unbounded; a tie goes to degree 1, the cheaper per DoF).
   */
  unsigned int
  race_winner(const RacerState &degree_1, const RacerState &degree_2);
} // namespace FloorBlock::Studies
