#include <app/command_options.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <iostream>

namespace FloorBlock::App
{
  Parameters::ScenarioParameters
  read_scene(const CommandOptions &options)
  {
    auto scene =
      Parameters::read_scenario(options.scene_path, options.overrides);
    // The closed-form commands run without MPI; under mpirun one process
    // speaks for all.
    int mpi_started = 0;
    MPI_Initialized(&mpi_started);
    if (!mpi_started ||
        dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        for (const std::string &warning : scene.warnings)
          std::cerr << "warning: " << warning << std::endl;
        if (!scene.joints.stiffness_origin.empty())
          std::cout << "joint stiffness: " << scene.joints.stiffness_origin
                    << std::endl;
      }
    return scene;
  }

  void
  require_plane_scene(const Parameters::ScenarioParameters &scene,
                      const std::string                    &command)
  {
    if (scene.geometry.dimension != 2)
      throw InputError("Geometry/Dimension",
                       std::to_string(scene.geometry.dimension),
                       "must be 2 for `" + command +
                         "`: so far only `floorblock solve` solves 3D "
                         "scenes; `floorblock mesh` builds the 3D "
                         "mesh");
  }

  std::string
  output_directory(const CommandOptions                 &options,
                   const Parameters::ScenarioParameters &scene)
  {
    if (!options.output_directory.empty())
      return options.output_directory;
    return (std::filesystem::path("results") / scene.scene_name).string();
  }
} // namespace FloorBlock::App
