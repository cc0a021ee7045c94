#include <app/command_options.h>
#include <common/input_error.h>
#include <geometry/body_outline.h>
#include <scene/assembly_inputs.h>

#include <deal.II/base/timer.h>

#include <fmt/format.h>
#include <studies/corner_report.h>
#include <studies/rounding_study.h>

#include <iostream>

namespace FloorBlock::App
{
  namespace
  {
    /**
     * Every radius of the rounding study must fit the blocks (the outline
     * builder's check), before anything is solved or written.
     */
    void
    check_rounding_radii(const Parameters::ScenarioParameters &scene)
    {
      for (const double radius : scene.corner.rounding_radii)
        {
          Parameters::ScenarioParameters rounded  = scene;
          rounded.geometry.corner_rounding_radius = radius;
          try
            {
              Geometry::build_outline(Scene::assembly_description(rounded));
            }
          catch (const InputError &error)
            {
              throw InputError("Corner/Rounding radii",
                               fmt::format("{}", radius),
                               std::string("every radius must fit the block "
                                           "corners: ") +
                                 error.what());
            }
        }
    }
  } // namespace

  int
  corner_command(const CommandOptions &options)
  {
    const auto scene = read_scene(options);
    require_plane_scene(scene, "corner");
    if (scene.model.chosen != Parameters::BlockModel::elastic)
      throw InputError("Model/Blocks",
                       "rigid",
                       "the corner field needs the elastic FEM (elastic, or "
                       "auto with Model/Outputs = contact stress)");
    check_rounding_radii(scene);

    const Output::ResultFolder folder(output_directory(options, scene));
    folder.mark_unfinished();
    folder.write_inputs(scene);
    dealii::Timer clock;
    const auto    seconds_left = [&]() {
      return scene.corner.time_budget - clock.wall_time();
    };
    const auto progress = [](const std::string &line) {
      std::cout << line << std::endl;
    };

    const Studies::CornerAnalysis analysis =
      Studies::analyse_corner(scene,
                              Output::ResultFolder(folder.path_of("zoom")),
                              seconds_left,
                              progress);
    const Studies::RoundingStudy rounding =
      Studies::rounding_study(scene,
                              analysis,
                              Output::ResultFolder(folder.path_of("rounding")),
                              seconds_left,
                              progress);

    Studies::write_corner_report(
      folder, scene, analysis, rounding, clock.wall_time());
    std::cout << Studies::corner_summary_lines(analysis, rounding) << "wrote "
              << folder.path_of("corner.json") << std::endl;
    return analysis.levels.empty() ? exit_code::failure : exit_code::success;
  }
} // namespace FloorBlock::App
