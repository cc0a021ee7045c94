#include <common/wall_clock.h>
#include <pipeline/case_runner.h>

#include <deal.II/base/mpi.h>

#include <assessment/safety_cases.h>

#include <filesystem>

namespace FloorBlock::Assessment
{
  CaseBatch
  solve_safety_cases(const SceneSource       &source,
                     const CaseDraws         &draws,
                     const Output::CaseStore &store,
                     const MPI_Comm           communicator,
                     std::ostream            &progress)
  {
    CaseBatch batch;
    // A record of other inputs (a study drawn with another seed or size)
    // is removed by the first rank and computed anew.
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      for (std::size_t k = 0; k < draws.ids.size(); ++k)
        if (store.has(draws.ids[k]) &&
            safety_case_from_json(store.load(draws.ids[k])).inputs !=
              draws.points[k])
          std::filesystem::remove(store.path_of(draws.ids[k]));
    MPI_Barrier(communicator);

    std::vector<Pipeline::SweepCase> cases;
    for (std::size_t k = 0; k < draws.ids.size(); ++k)
      {
        if (store.has(draws.ids[k]))
          ++batch.n_from_earlier_runs;
        cases.push_back({draws.ids[k], [&, k](const Output::CaseStore &s) {
                           s.store(draws.ids[k],
                                   to_json(solve_safety_case(source,
                                                             draws.ids[k],
                                                             draws.points[k])));
                         }});
      }

    int stopped = 0;
    try
      {
        Pipeline::run_cases(cases, store, communicator, progress);
      }
    catch (const DeadlineReached &)
      {
        stopped = 1;
      }
    // Every rank waits for the others' records before reading them.
    const int any_stopped = dealii::Utilities::MPI::max(stopped, communicator);
    batch.complete        = any_stopped == 0;

    for (std::size_t k = 0; k < draws.ids.size(); ++k)
      if (store.has(draws.ids[k]))
        {
          SafetyCase record = safety_case_from_json(store.load(draws.ids[k]));
          if (record.inputs != draws.points[k])
            throw std::runtime_error("the stored case " +
                                     store.path_of(draws.ids[k]) +
                                     " changed while the study ran");
          batch.cases.push_back(std::move(record));
        }
      else
        batch.complete = false;
    return batch;
  }
} // namespace FloorBlock::Assessment
