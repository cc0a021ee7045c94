#include <app/command_options.h>
#include <output/fem_summary.h>
#include <pipeline/fem_pipeline.h>

#include <iostream>

namespace FloorBlock::App
{
  int
  solve_command(const CommandOptions &options)
  {
    // Geometry/Dimension = 3 too: one process, Pipeline::solve_swept_scene.
    const auto scene = read_scene(options);
    if (scene.geometry.dimension == 3)
      Pipeline::check_swept_scene(scene);
    const Output::ResultFolder folder(output_directory(options, scene));
    folder.write_inputs(scene);
    const Pipeline::FemOutcome outcome = Pipeline::solve_scene(scene, folder);
    std::cout << Output::fem_summary_text(outcome.report, outcome.result,
                                          outcome.mesh)
              << "wrote "
              << folder.path_of("fem.json") << ", "
              << folder.path_of("joints.csv") << std::endl;
    return outcome.converged ? exit_code::success : exit_code::failure;
  }
} // namespace FloorBlock::App
