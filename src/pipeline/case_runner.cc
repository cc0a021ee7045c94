#include <common/interrupt.h>
#include <pipeline/case_runner.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <fmt/format.h>

#include <ostream>

namespace FloorBlock::Pipeline
{
  SweepProgress
  run_cases(const std::vector<SweepCase> &cases,
            const Output::CaseStore      &store,
            const MPI_Comm                communicator,
            std::ostream                 &progress)
  {
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(communicator);

    std::vector<const SweepCase *> mine;
    for (std::size_t k = rank; k < cases.size(); k += n_ranks)
      mine.push_back(&cases[k]);

    SweepProgress result;
    dealii::Timer timer;
    result.n_cases = mine.size();
    for (const SweepCase *sweep_case : mine)
      {
        stop_if_interrupted();
        if (store.has(sweep_case->id))
          {
            ++result.n_skipped;
            continue;
          }
        sweep_case->compute_and_store(store);
        ++result.n_computed;

        const double       elapsed = timer.wall_time();
        const unsigned int n_left =
          result.n_cases - result.n_skipped - result.n_computed;
        progress
          << fmt::format("[rank {}] {}/{} cases done ({} from an earlier run), "
                         "{:.1f} s elapsed, about {:.0f} s left ({})\n",
                         rank,
                         result.n_skipped + result.n_computed,
                         result.n_cases,
                         result.n_skipped,
                         elapsed,
                         elapsed / result.n_computed * n_left,
                         sweep_case->id)
          << std::flush;
      }
    result.wall_time = timer.wall_time();
    return result;
  }
} // namespace FloorBlock::Pipeline
