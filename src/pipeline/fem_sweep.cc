#include <pipeline/case_runner.h>
#include <pipeline/fem_pipeline.h>
#include <pipeline/fem_sweep.h>
#include <common/units.h>
#include <output/fem_sweep_report.h>
#include <output/gnuplot.h>
#include <scene/rigid_inputs.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <iostream>
#include <set>

#include <unistd.h>

namespace FloorBlock::Pipeline
{
  using nlohmann::json;

  namespace
  {
    /// Removes the scratch folder of a case however its solve ends.
    struct ScratchFolder
    {
      std::filesystem::path path;
      ~ScratchFolder()
      {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
      }
    };

    /// Case file name: rigid-block cases are stored apart, so a rigid and
    /// an elastic sweep into one folder never take each other's cases.
    std::string
    case_id(const Scene::FigurePoint &point)
    {
      return Scene::uses_rigid_blocks(point.scene) ? point.id() + "_rigid" :
                                                     point.id();
    }

    json
    fem_case(const Scene::FigurePoint &point)
    {
      const ScratchFolder scratch{std::filesystem::temp_directory_path() /
                                  ("floorblock_case_" +
                                   std::to_string(::getpid()) + "_" +
                                   point.id())};
      const FemOutcome outcome =
        solve_scene(point.scene, Output::ResultFolder(scratch.path.string()),
                    false);
      return Output::fem_case_record(point, outcome.result, outcome.report);
    }
  } // namespace

  unsigned int
  run_fem_sweep(const std::vector<Scene::FigurePoint> &points,
                const Output::ResultFolder &           folder,
                const unsigned int                     limit)
  {
    const Output::CaseStore store(folder.path_of("cases"));
    std::vector<SweepCase>  cases;
    for (const auto &point : points)
      if (limit == 0 || cases.size() < limit)
        cases.push_back({case_id(point), [&point] { return fem_case(point); }});

    run_cases(cases, store, MPI_COMM_WORLD, std::cout);
    MPI_Barrier(MPI_COMM_WORLD);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return 0;

    std::vector<json> records;
    for (const auto &point : points)
      if (store.has(case_id(point)))
        records.push_back(store.load(case_id(point)));
    std::set<std::string> figures;
    for (const auto &record : records)
      figures.insert(record["figure"].get<std::string>());
    for (const std::string &figure : figures)
      {
        folder.write("sweep_fem_" + figure + ".csv",
                     Output::fem_sweep_csv(records, figure));
        Output::render_png(Output::fem_sweep_plot(records, figure),
                           folder.path_of("sweep_fem_" + figure + ".png"),
                           1600, 500);
      }
    return points.size() - records.size();
  }
} // namespace FloorBlock::Pipeline
