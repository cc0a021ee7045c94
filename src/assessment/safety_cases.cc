#include <assessment/safety_cases.h>
#include <common/wall_clock.h>
#include <pipeline/case_runner.h>

#include <deal.II/base/mpi.h>

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
    const int any_stopped =
      dealii::Utilities::MPI::max(stopped, communicator);
    batch.complete = any_stopped == 0;

    for (std::size_t k = 0; k < draws.ids.size(); ++k)
      if (store.has(draws.ids[k]))
        {
          SafetyCase record = safety_case_from_json(store.load(draws.ids[k]));
          if (record.inputs != draws.points[k])
            throw std::runtime_error(
              "the stored case " + store.path_of(draws.ids[k]) +
              " holds other inputs than this study draws: the folder holds "
              "another study's cases (remove it, or choose --output)");
          batch.cases.push_back(std::move(record));
        }
      else
        batch.complete = false;
    return batch;
  }
} // namespace FloorBlock::Assessment
