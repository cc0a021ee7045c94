#include <common/wall_clock.h>

#include <chrono>
#include <limits>

namespace FloorBlock
{
  namespace
  {
    using Clock = std::chrono::steady_clock;

    Clock::time_point &
    start_time()
    {
      static Clock::time_point start = Clock::now();
      return start;
    }

    double solve_deadline = std::numeric_limits<double>::infinity();
  } // namespace

  void
  start_wall_clock()
  {
    start_time() = Clock::now();
  }

  double
  seconds_since_start()
  {
    return std::chrono::duration<double>(Clock::now() - start_time()).count();
  }

  void
  set_solve_deadline(const double seconds)
  {
    solve_deadline = seconds;
  }

  void
  clear_solve_deadline()
  {
    solve_deadline = std::numeric_limits<double>::infinity();
  }

  bool
  solve_deadline_passed()
  {
    return seconds_since_start() > solve_deadline;
  }
} // namespace FloorBlock
