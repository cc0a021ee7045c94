// Solver/FE degree = auto (studies/degree_race): whose turn it is, and
// whose solve is reported.

#include <gtest/gtest.h>
#include <studies/degree_race.h>

using namespace FloorBlock::Studies;

namespace
{
  RacerState
  running(const double time_spent, const bool checked = true)
  {
    RacerState state;
    state.joined     = true;
    state.checked    = checked;
    state.time_spent = time_spent;
    return state;
  }

  RacerState
  stopped(const double time_spent, const std::optional<double> error)
  {
    RacerState state     = running(time_spent);
    state.finished       = true;
    state.reported_error = error;
    return state;
  }
} // namespace

// The tool shall solve degree 1's level 0 and its check before degree 2
// starts, and not start degree 2 when that pair meets the target, also
// while the next level confirms it.
TEST(DegreeRace, DegreeTwoWaitsForDegreeOnesLevelZeroPair)
{
  const RacerState absent;
  EXPECT_EQ(next_race_turn(running(0., false), absent), RaceTurn::degree_1);
  RacerState confirming = running(5.);
  confirming.confirming = true;
  EXPECT_EQ(next_race_turn(confirming, absent), RaceTurn::degree_1);
  RacerState met = stopped(7., 0.004);
  met.met        = true;
  EXPECT_EQ(next_race_turn(met, absent), RaceTurn::over);
  EXPECT_EQ(race_winner(met, absent), 1u);
  // Level 0 checked, not met: degree 2 joins.
  EXPECT_EQ(next_race_turn(running(55.), absent), RaceTurn::degree_2);
  // Degree 1 stopped without an estimate (level 0 failed): degree 2 tries.
  EXPECT_EQ(next_race_turn(stopped(3., std::nullopt), absent),
            RaceTurn::degree_2);
}

// The tool shall step the loop with less time spent, degree 1 on a tie,
// and the one still running once the other has stopped.
TEST(DegreeRace, LoopWithLessTimeSpentStepsNext)
{
  EXPECT_EQ(next_race_turn(running(55.), running(50.)), RaceTurn::degree_2);
  EXPECT_EQ(next_race_turn(running(55.), running(390.)), RaceTurn::degree_1);
  EXPECT_EQ(next_race_turn(running(55.), running(55.)), RaceTurn::degree_1);
  EXPECT_EQ(next_race_turn(stopped(10., 0.3), running(390.)),
            RaceTurn::degree_2);
  EXPECT_EQ(next_race_turn(running(900.), stopped(400., 0.02)),
            RaceTurn::degree_1);
  EXPECT_EQ(next_race_turn(stopped(900., 0.02), stopped(400., 0.03)),
            RaceTurn::over);
}

// The tool shall end the race once either loop ran out of the time budget
// both share: degree 2 does not join, and a running loop steps no more.
TEST(DegreeRace, SharedBudgetSpentEndsTheRace)
{
  RacerState out_of_time  = stopped(9., 0.08);
  out_of_time.out_of_time = true;
  EXPECT_EQ(next_race_turn(out_of_time, RacerState()), RaceTurn::over);
  EXPECT_EQ(next_race_turn(running(5.), out_of_time), RaceTurn::over);
  EXPECT_EQ(next_race_turn(out_of_time, running(20.)), RaceTurn::over);
  EXPECT_EQ(race_winner(out_of_time, RacerState()), 1u);
}

// The tool shall let a loop whose pair met the target confirm it before
// the other loop steps again, whatever their times.
TEST(DegreeRace, ConfirmationComesFirst)
{
  RacerState confirming = running(700.);
  confirming.confirming = true;
  EXPECT_EQ(next_race_turn(confirming, running(500.)), RaceTurn::degree_1);
  EXPECT_EQ(next_race_turn(running(300.), confirming), RaceTurn::degree_2);
}

// The tool shall report the degree that met the target, else the one with
// the smaller estimate (none counts as unbounded, a tie goes to degree 1).
TEST(DegreeRace, WinnerMetTheTargetOrHasTheSmallerEstimate)
{
  RacerState met_2 = stopped(400., 0.008);
  met_2.met        = true;
  EXPECT_EQ(next_race_turn(running(390.), met_2), RaceTurn::over);
  EXPECT_EQ(race_winner(running(390.), met_2), 2u);
  EXPECT_EQ(race_winner(stopped(900., 0.02), stopped(400., 0.03)), 1u);
  EXPECT_EQ(race_winner(stopped(900., 0.03), stopped(400., 0.02)), 2u);
  EXPECT_EQ(race_winner(stopped(900., std::nullopt), stopped(400., 0.5)), 2u);
  EXPECT_EQ(race_winner(stopped(900., 0.02), stopped(400., 0.02)), 1u);
}
