#pragma once

namespace FloorBlock
{
  /**
   * @brief Runs OpenBLAS on one thread, unless the user chose a count
   * (OPENBLAS_NUM_THREADS, GOTO_NUM_THREADS or OMP_NUM_THREADS set) or
   * the BLAS in the process is not OpenBLAS. Returns whether it set it.
   *
   * Why: the BLAS calls here come from UMFPACK's dense frontal matrices
   * on 2D meshes, which are small, and OpenBLAS's pthread build starts a
   * thread per core that spins between calls. Measured on this 2-core
   * machine (Release):
   * - `floorblock run params/default.prm`: 8.7-11.0 s wall with 5.6-6.1 s
   *   of system time by default, 8.5-9.0 s with 0.2 s on one thread;
   * - a 92k-DoF solve (Global refinements = 2): 29.3 s against 28.8 s;
   * - the 23 scenario tests under ctest -j2: 60 s against 42 s, as the
   *   spinning thread takes the core the other test runs on.
   * The 3D solves under mpirun (ML and GMRES, no dense fronts) did not
   * change.
   *
   * OpenBLAS reads its variables when it is loaded, before main(), so
   * the count is set through openblas_set_num_threads, looked up at run
   * time: no link dependency on OpenBLAS (Debian's libblas.so.3 may be the
   * reference BLAS).
   */
  bool
  limit_blas_to_one_thread();

  /**
   * @brief OpenBLAS's current thread count (openblas_get_num_threads), or
   * 0 if the process has no OpenBLAS.
   */
  int
  blas_thread_count();
} // namespace FloorBlock
