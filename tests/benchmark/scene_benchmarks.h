#pragma once

#include "benchmark_options.h"

namespace FloorBlock::Benchmark
{
  /**
   * @brief Registers, per refinement r (in increasing order, so the time
   * limit can stop finer levels), the benchmarks
   * default/r<r>/{mesh, assembly_cold, assembly_warm, bulk_reuse,
   * linear_solve,
   * klu_phases, umfpack_phases, newton_iteration, contact_solve/<law>};
   * they fill records().
   */
  void
  register_scene_benchmarks(const BenchmarkOptions &options);

  /** @brief Registers hertz/level<l>: run_hertz_verification per level. */
  void
  register_hertz_benchmarks(const BenchmarkOptions &options);
} // namespace FloorBlock::Benchmark
