// The command's wall clock and the solve deadline that bounds `run`'s time
// budget (common/wall_clock.h): long solves check it at their safe points
// through stop_if_interrupted().
#include <common/interrupt.h>
#include <common/wall_clock.h>

#include <gtest/gtest.h>

using namespace FloorBlock;

// The tool shall let a solve run on while no deadline is set or the
// deadline lies ahead, and stop it at its next safe point once the
// deadline has passed.
TEST(WallClock, PassedDeadlineStopsAtTheNextSafePoint)
{
  start_wall_clock();
  EXPECT_GE(seconds_since_start(), 0.);
  EXPECT_NO_THROW(stop_if_interrupted());
  {
    const ScopedSolveDeadline ahead(seconds_since_start() + 3600.);
    EXPECT_FALSE(solve_deadline_passed());
    EXPECT_NO_THROW(stop_if_interrupted());
  }
  {
    const ScopedSolveDeadline passed(seconds_since_start() - 1.);
    EXPECT_TRUE(solve_deadline_passed());
    EXPECT_THROW(stop_if_interrupted(), DeadlineReached);
  }
}

// The tool shall clear the deadline when its scope ends, also when the
// solve it bounded threw, so that a later solve runs to its end.
TEST(WallClock, DeadlineEndsWithItsScope)
{
  try
    {
      const ScopedSolveDeadline passed(0.);
      stop_if_interrupted();
      FAIL() << "the deadline did not stop the solve";
    }
  catch (const DeadlineReached &)
    {}
  EXPECT_FALSE(solve_deadline_passed());
  EXPECT_NO_THROW(stop_if_interrupted());
}
