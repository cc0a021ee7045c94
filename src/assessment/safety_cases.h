#pragma once

#include <output/case_store.h>

#include <assessment/safety_case.h>
#include <mpi.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace FloorBlock::Assessment
{
  /** @brief Cases with their inputs, in order. */
  struct CaseDraws
  {
    std::vector<std::string>         ids;
    std::vector<std::vector<double>> points; ///< one per id
  };

  /** @brief What a batch of FEM cases gave. */
  struct CaseBatch
  {
    /** Every case of the draws with a record, in the draws' order. */
    std::vector<SafetyCase> cases;
    /** Whether every case has a record (else the solve deadline came). */
    bool complete = true;
    /** Of the records, those an earlier run had stored. */
    unsigned int n_from_earlier_runs = 0;
  };

  /**
   * @brief Solves the cases of @p draws without a record in @p store with
   * the FEM (solve_safety_case()), spread over the ranks of @p communicator
   * (Pipeline::run_cases: case k on rank k mod size, a progress line per
   * case on @p progress), each record stored as it finishes; then every
   * rank reads every record. A stored record of other inputs than its
   * draw (a study drawn with another seed or size) is computed anew. A
   * passed solve deadline (ScopedSolveDeadline) stops the batch at its
   * next safe point, leaving the finished records: a rerun resumes.
   */
  CaseBatch
  solve_safety_cases(const SceneSource       &source,
                     const CaseDraws         &draws,
                     const Output::CaseStore &store,
                     MPI_Comm                 communicator,
                     std::ostream            &progress);
} // namespace FloorBlock::Assessment
