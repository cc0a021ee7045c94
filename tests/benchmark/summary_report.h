#pragma once

#include <string>
#include <utility>
#include <vector>

#include "loaded_blas.h"
#include "measurements.h"

namespace FloorBlock::Benchmark
{
  /**
   * @brief Exponent p of the least-squares fit log t = c + p log n over
   * (n, t) points; needs two points with distinct n.
   * @return p, or NaN (and the caller prints "n/a") with fewer points.
   */
  double
  power_law_exponent(const std::vector<std::pair<double, double>> &points);

  /** @brief What the process saw around the measurements. */
  struct RunContext
  {
    LoadedBlas   blas;
    std::string  load_before; ///< /proc/loadavg at start
    std::string  load_after;  ///< /proc/loadavg at the end
    unsigned int n_cores = 0;
  };

  /** @brief /proc/loadavg as one line. */
  std::string
  load_average();

  /**
   * @brief Markdown tables of everything in @p all: per level the stage
   * times, direct-solver phases, whole contact solves with their TimerOutput
   * sections and whole/linear cost ratio, the fitted exponents, the face-joint
   * contact length against the finest level, and the Hertz runs.
   */
  std::string
  summary_markdown(const Records &all, const RunContext &context);
} // namespace FloorBlock::Benchmark
