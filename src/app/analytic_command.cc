#include <app/command_options.h>
#include <output/analytic_report.h>
#include <output/result_folder.h>
#include <scene/closed_forms.h>

#include <iostream>

namespace FloorBlock::App
{
  int
  analytic_command(const CommandOptions &options)
  {
    const auto scene        = read_scene(options);
    const auto closed_forms = Scene::evaluate_closed_forms(scene);

    const Output::ResultFolder folder(output_directory(options, scene));
    folder.write_inputs(scene);
    folder.write_json("analytic.json", Output::analytic_json(closed_forms));
    folder.write("analytic.csv", Output::analytic_csv(closed_forms));

    std::cout << "Closed forms for scene '" << scene.scene_name << "'"
              << Output::analytic_table(closed_forms) << "\nwrote "
              << folder.path_of("analytic.json") << ", "
              << folder.path_of("analytic.csv") << std::endl;
    return 0;
  }
} // namespace FloorBlock::App
