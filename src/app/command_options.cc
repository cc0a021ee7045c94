#include <app/command_options.h>

#include <filesystem>

namespace FloorBlock::App
{
  Parameters::ScenarioParameters
  read_scene(const CommandOptions &options)
  {
    return Parameters::read_scenario(options.scene_path, options.overrides);
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
