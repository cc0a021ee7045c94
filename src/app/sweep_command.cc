#include <app/command_options.h>
#include <common/input_error.h>
#include <common/units.h>
#include <output/gnuplot.h>
#include <output/result_folder.h>
#include <output/sweep_report.h>
#include <pipeline/fem_sweep.h>
#include <scene/chapter_figures.h>

#include <deal.II/base/mpi.h>

#include <fmt/format.h>

#include <iostream>
#include <set>

namespace FloorBlock::App
{
  namespace
  {
    int
    fem_sweep_command(const CommandOptions                 &options,
                      const Parameters::ScenarioParameters &scene)
    {
      const std::set<std::string> figures = {"fig6_5",
                                             "fig6_6",
                                             "fig6_7",
                                             "fig6_10_11"};
      if (!options.figure.empty() && figures.count(options.figure) == 0)
        throw InputError("--figure",
                         options.figure,
                         "one of fig6_5, fig6_6, fig6_7, fig6_10_11");
      std::vector<Scene::FigurePoint> points;
      for (auto &&list : {Scene::lateral_force_figures(scene),
                          Scene::floor_stress_figures(scene)})
        for (const auto &point : list)
          if (options.figure.empty() || point.figure == options.figure)
            points.push_back(point);

      const Output::ResultFolder folder(output_directory(options, scene));
      folder.write_inputs(scene);
      const unsigned int remaining =
        Pipeline::run_fem_sweep(points, folder, options.case_limit);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << points.size() - remaining << " of " << points.size()
                  << " FEM cases finished; results in "
                  << output_directory(options, scene) << std::endl;
      return 0;
    }
  } // namespace

  int
  sweep_command(const CommandOptions &options)
  {
    const auto scene = read_scene(options);
    if (options.with_fem)
      {
        require_plane_scene(scene, "sweep --fem");
        return fem_sweep_command(options, scene);
      }
    const Output::ResultFolder folder(output_directory(options, scene));
    folder.write_inputs(scene);

    const auto lateral = Scene::lateral_force_figures(scene);
    folder.write("sweep_fig6_5_6_7.csv", Output::sweep_csv(lateral));
    for (const auto &[figure, title] :
         std::vector<std::pair<std::string, std::string>>{
           {"fig6_5",
            fmt::format("Figure 6.5: Q at the face, planar bedding {:.1f} deg",
                        Units::radians_to_degrees(scene.bedding.inclination))},
           {"fig6_6", "Figure 6.6: Q at the face, y = x^2/400"},
           {"fig6_7", "Figure 6.7: Q at the face, y = x^2/200"}})
      Output::render_png(Output::lateral_force_plot(lateral, figure, title),
                         folder.path_of("sweep_" + figure + ".png"),
                         1500,
                         500);

    const auto stress = Scene::floor_stress_figures(scene);
    folder.write("sweep_fig6_10_11.csv", Output::sweep_csv(stress));
    for (const double curvature : {400.0, 200.0, 100.0, 50.0})
      Output::render_png(
        Output::floor_stress_plot(stress, curvature),
        folder.path_of(fmt::format("sweep_fig6_10_11_k{:.0f}.png", curvature)),
        1500,
        500);

    std::cout << "evaluated " << lateral.size() + stress.size()
              << " closed-form points; wrote sweep_*.csv and sweep_*.png to "
              << output_directory(options, scene) << std::endl;
    return 0;
  }
} // namespace FloorBlock::App
