#include <app/command_options.h>
#include <output/analytic_report.h>
#include <output/result_folder.h>
#include <scene/closed_forms.h>

#include <algorithm>
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

    std::vector<unsigned int> loaded = scene.loaded_blocks();
    std::sort(loaded.begin(), loaded.end());
    std::cout << "Support load on blocks";
    for (const unsigned int block : loaded)
      std::cout << (block == loaded.front() ? " " : ", ") << block;
    std::cout << (loaded.empty() ? " none" : "")
              << " (1 = free end, the numbering of every output; "
                 "Loading/Loaded blocks from face counts from the face)\n";
    std::cout << "Closed forms for scene '" << scene.scene_name << "'"
              << Output::analytic_table(closed_forms) << "\nwrote "
              << folder.path_of("analytic.json") << ", "
              << folder.path_of("analytic.csv") << std::endl;
    return 0;
  }
} // namespace FloorBlock::App
