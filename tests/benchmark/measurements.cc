#include "measurements.h"

#include <ctime>

namespace FloorBlock::Benchmark
{
  namespace
  {
    double
    clock_seconds(const clockid_t clock)
    {
      timespec now{};
      clock_gettime(clock, &now);
      return static_cast<double>(now.tv_sec) + 1e-9 * now.tv_nsec;
    }
  } // namespace

  Stopwatch::Stopwatch()
    : wall_start(clock_seconds(CLOCK_MONOTONIC))
    , cpu_start(clock_seconds(CLOCK_PROCESS_CPUTIME_ID))
  {}

  double
  Stopwatch::wall_seconds() const
  {
    return clock_seconds(CLOCK_MONOTONIC) - wall_start;
  }

  double
  Stopwatch::cpu_seconds() const
  {
    return clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu_start;
  }

  Records &
  records()
  {
    static Records all;
    return all;
  }
} // namespace FloorBlock::Benchmark
