#pragma once

#include <string>
#include <vector>

namespace FloorBlock::Benchmark
{
  /** @brief The BLAS/LAPACK this process runs with. */
  struct LoadedBlas
  {
    /** "OpenBLAS", "reference BLAS" or "unknown". */
    std::string name;
    /** Paths of the BLAS and LAPACK libraries mapped into the process. */
    std::vector<std::string> libraries;
    /** True if OpenBLAS was found and limited to one thread. */
    bool limited_to_one_thread = false;
  };

  /**
   * @brief Reads /proc/self/maps for the BLAS and LAPACK libraries the
   * dynamic loader picked (LD_LIBRARY_PATH chooses per process, the system
   * alternatives stay untouched) and limits OpenBLAS to one thread, so the
   * whole benchmark uses one core.
   */
  LoadedBlas
  inspect_and_limit_blas();
} // namespace FloorBlock::Benchmark
