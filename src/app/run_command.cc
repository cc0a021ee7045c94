#include <app/command_options.h>
#include <output/analytic_report.h>
#include <output/result_folder.h>
#include <scene/closed_forms.h>

#include <iostream>

namespace FloorBlock::App
{
  int
  run_command(const CommandOptions &options)
  {
    const auto scene        = read_scene(options);
    const auto closed_forms = Scene::evaluate_closed_forms(scene);

    const Output::ResultFolder folder(output_directory(options, scene));
    folder.mark_unfinished();
    folder.write_inputs(scene);
    const auto analytic = Output::analytic_json(closed_forms);
    folder.write_json("analytic.json", analytic);
    folder.write("analytic.csv", Output::analytic_csv(closed_forms));

    std::cout << "Closed forms for scene '" << scene.scene_name << "'"
              << Output::analytic_table(closed_forms) << std::endl;

    // The FEM half is not wired into `run` yet: say so in the marker file
    // instead of leaving the fem section silently absent.
    folder.write_summary({{"status", "analytic_only"},
                          {"status_text", "FEM stages are not part of this "
                                          "build's run pipeline yet"},
                          {"scene", scene.scene_name},
                          {"analytic", analytic}});
    std::cout << "wrote " << folder.path_of("summary.json") << std::endl;
    return 0;
  }
} // namespace FloorBlock::App
