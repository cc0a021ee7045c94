#pragma once

#include <output/case_store.h>

#include <mpi.h>

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace FloorBlock::Pipeline
{
  /** One case of a sweep: a stable id (its file name) and how to compute it. */
  struct SweepCase
  {
    std::string id;
    /** Computes the case and stores its record in the store under id. */
    std::function<void(const Output::CaseStore &)> compute_and_store;
  };

  /** What one rank did. */
  struct SweepProgress
  {
    unsigned int n_cases    = 0; ///< on this rank
    unsigned int n_skipped  = 0; ///< already finished by an earlier run
    unsigned int n_computed = 0;
    double       wall_time  = 0; ///< s
  };

  /**
   * @brief Runs the cases that have no finished file yet, and stores each
   * one as soon as it is done.
   *
   * The cases are split statically over the MPI ranks of @p communicator
   * (case k goes to rank k mod size): under `mpirun -np N` the N ranks work
   * in parallel on their own cases, each with serial linear algebra, which
   * is the cheapest parallelism for many small independent solves. Between
   * cases it checks for SIGINT/SIGTERM and throws Interrupted; an interrupted
   * case leaves no file. Prints one progress line per case on @p progress:
   * cases done / total, elapsed and estimated remaining time.
   */
  SweepProgress
  run_cases(const std::vector<SweepCase> &cases,
            const Output::CaseStore      &store,
            const MPI_Comm                communicator,
            std::ostream                 &progress);
} // namespace FloorBlock::Pipeline
