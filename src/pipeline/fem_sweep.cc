#include <common/units.h>
#include <output/fem_sweep_report.h>
#include <pipeline/case_runner.h>
#include <pipeline/fem_pipeline.h>
#include <pipeline/fem_sweep.h>
#include <pipeline/scratch_folder.h>
#include <scene/rigid_inputs.h>

#include <deal.II/base/mpi.h>

#include <iostream>

namespace FloorBlock::Pipeline
{
  namespace
  {
    /// Case file name: rigid-block cases are stored apart, so a rigid and
    /// an elastic sweep into one folder never take each other's cases.
    std::string
    case_id(const Scene::FigurePoint &point)
    {
      return Scene::uses_rigid_blocks(point.scene) ? point.id() + "_rigid" :
                                                     point.id();
    }

    void
    fem_case(const Scene::FigurePoint &point, const Output::CaseStore &store)
    {
      const ScratchFolder scratch(point.id());
      const FemOutcome    outcome =
        solve_scene(point.scene,
                    Output::ResultFolder(scratch.path.string()),
                    false);
      store.store(case_id(point),
                  Output::fem_case_json(Output::fem_case_record(
                    point, outcome.result, outcome.report)));
    }
  } // namespace

  unsigned int
  run_fem_sweep(const std::vector<Scene::FigurePoint> &points,
                const Output::ResultFolder            &folder,
                const unsigned int                     limit)
  {
    const Output::CaseStore store(folder.path_of("cases"));
    std::vector<SweepCase>  cases;
    for (const auto &point : points)
      if (limit == 0 || cases.size() < limit)
        cases.push_back({case_id(point), [&point](const auto &case_store) {
                           fem_case(point, case_store);
                         }});

    run_cases(cases, store, MPI_COMM_WORLD, std::cout);
    MPI_Barrier(MPI_COMM_WORLD);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return 0;

    std::vector<std::string> case_ids;
    for (const auto &point : points)
      case_ids.push_back(case_id(point));
    return points.size() - Output::write_fem_sweep(store, case_ids, folder);
  }
} // namespace FloorBlock::Pipeline
