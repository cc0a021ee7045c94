#include <app/command_options.h>
#include <common/input_error.h>
#include <output/fem_summary.h>
#include <pipeline/fem_pipeline.h>

#include <deal.II/base/mpi.h>

#include <iostream>

namespace FloorBlock::App
{
  int
  solve_command(const CommandOptions &options)
  {
    // Geometry/Dimension = 3 too (Pipeline::solve_swept_scene), on one
    // process or, under mpirun, with one mesh over all processes; every
    // process computes the same files, the first one writes them.
    const auto         scene = read_scene(options);
    const unsigned int n_processes =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const bool first_process =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    if (scene.geometry.dimension == 3)
      Pipeline::check_swept_scene(scene);
    else if (n_processes > 1)
      throw InputError("Geometry/Dimension",
                       "2",
                       "3 when solve runs on several processes (mpirun -np " +
                         std::to_string(n_processes) +
                         "): a 2D scene solves on one process; sweep runs "
                         "its cases over several");
    const Output::ResultFolder folder(output_directory(options, scene),
                                      first_process);
    folder.write_inputs(scene);
    const Pipeline::FemOutcome outcome = Pipeline::solve_scene(scene, folder);
    if (first_process)
      std::cout << Output::fem_summary_text(outcome.report,
                                            outcome.result,
                                            outcome.mesh)
                << "wrote " << folder.path_of("fem.json") << ", "
                << folder.path_of("joints.csv") << std::endl;
    return outcome.converged ? exit_code::success : exit_code::failure;
  }
} // namespace FloorBlock::App
