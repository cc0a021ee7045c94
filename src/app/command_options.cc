#include <app/command_options.h>

#include <filesystem>

namespace FloorBlock::App
{
  Parameters::ScenarioParameters
  read_scene(const CommandOptions &options)
  {
    return Parameters::read_scenario(options.scene_path, options.overrides);
  }

  std::string
  output_directory(const CommandOptions &                options,
                   const Parameters::ScenarioParameters &scene)
  {
    if (!options.output_directory.empty())
      return options.output_directory;
    return (std::filesystem::path("results") / scene.scene_name).string();
  }
} // namespace FloorBlock::App
