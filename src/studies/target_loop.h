#pragma once

#include <output/fem_error_estimate.h>
#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>
#include <pipeline/fem_pipeline.h>

#include <studies/adaptive_levels.h>
#include <studies/degree_race.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Studies
{
  /**
   * @brief One FE degree's accuracy loop (solve_to_target()), one solve
   * per step(): level 0, a level's check (every cell halved) or the next
   * adaptive level. Stepping lets two degrees' loops run turn about
   * (degree_race.h); a single degree runs step() until finished().
   *
   * Level 0 is written into @p base_folder, level k into
   * <base_folder>/refined/level_<k>/, level k's check into
   * <base_folder>/refined/level_<k>_halved/. finish() copies the reported
   * solve's files into @p report_folder when they are elsewhere.
   *
   * Mesh/Refinement time budget bounds the command's wall time
   * (seconds_since_start(), common/wall_clock.h), shared by every loop of a
   * race: a level or check whose forecast would end past it is not
   * started, and one that runs past it anyway stops at its next load
   * increment (its folder is removed); the loop then reports its last
   * checked level. Only the command's first solve, without which there is
   * nothing to report, runs to its end whatever the budget
   * (@p first_solve_of_command).
   */
  class TargetLoop
  {
  public:
    TargetLoop(const Parameters::ScenarioParameters &scene,
               const Output::ResultFolder           &base_folder,
               const Output::ResultFolder           &report_folder,
               bool first_solve_of_command = true);

    /** Solves the next level or check; only while !finished(). */
    void
    step();

    bool
    finished() const;

    /** Whether a checked solve met the target (false while running). */
    bool
    met() const;

    /** Wall time (s) of this loop's steps so far. */
    double
    time_spent() const;

    /**
     * The smallest estimate among the checked solves so far, the one
     * finish() reports; none before the first check.
     */
    std::optional<double>
    reported_error() const;

    /** What the degree race needs to know (joined = true). */
    RacerState
    racer_state() const;

    /** The loop's record so far (levels, reported solve, stop reason). */
    const Output::AccuracyTarget &
    record() const;

    /**
     * Stops a loop that has not finished (another degree met the target
     * first): @p reason becomes its stop reason.
     */
    void
    abandon(const std::string &reason);

    /**
     * Copies the reported solve's files into the report folder and
     * returns the solve with its estimate (none when level 0 failed: its
     * fem.json says why).
     */
    std::pair<Pipeline::FemOutcome, std::optional<Output::FemErrorEstimate>>
    finish();

  private:
    enum class Action
    {
      solve_level,
      check_level,
      none
    };

    void
    solve_level();
    void
    check_level();
    /**
     * Runs @p solve under the budget's deadline (none for the command's
     * first solve); false if the deadline stopped it, which then becomes
     * the stop reason and finishes the loop.
     */
    bool
    solve_within_budget(const std::function<void()> &solve,
                        const std::string           &what,
                        const std::string           &folder);
    /** After level `level` is settled: the next level, or a stop. */
    void
    plan_next_level();
    /**
     * The level just solved confirms a pair that met the target: true
     * (and finished) if it lies inside every target figure's bracket;
     * otherwise the estimate is widened to contain it and the loop goes
     * on.
     */
    bool
    confirm_met_target();

    const Parameters::ScenarioParameters scene;
    const Output::ResultFolder           base_folder;
    const Output::ResultFolder           report_folder;
    const std::string                    face;
    AdaptiveLevels                       levels;
    Output::AccuracyTarget               target;
    // Every level's outcome is kept: the reported one is the last level
    // checked, which is not always the last solved.
    std::vector<Pipeline::FemOutcome> outcomes;
    // The reported level's check, when it is the check that is reported.
    std::optional<Pipeline::FemOutcome>     reported_halved;
    std::optional<Output::FemErrorEstimate> estimate;
    unsigned int                            level  = 0;
    Action                                  action = Action::solve_level;
    double                                  spent  = 0.;
    /** A checked pair met the target; the next level is to confirm it. */
    bool confirming = false;
    /** Stopped by Mesh/Refinement time budget (forecast or deadline). */
    bool out_of_time = false;
    /** Level 0 is the command's first solve: no deadline stops it. */
    const bool first_solve_of_command;
  };
} // namespace FloorBlock::Studies
