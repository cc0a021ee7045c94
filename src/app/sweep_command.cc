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
#include <studies/kn_safety_report.h>
#include <studies/kn_safety_sweep.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>

namespace FloorBlock::App
{
  namespace
  {
    std::string
    number_list(const std::set<double> &values)
    {
      std::string text;
      for (const double value : values)
        text += (text.empty() ? "" : ", ") + fmt::format("{}", value);
      return text;
    }

    /**
     * The grid points of the chosen figures, curvatures and load range, in
     * grid order; refuses a choice that selects nothing, naming what the
     * grid holds.
     */
    std::vector<Scene::FigurePoint>
    chosen_points(const CommandOptions                 &options,
                  const Parameters::ScenarioParameters &scene)
    {
      std::vector<Scene::FigurePoint> figure_points;
      for (auto &&list : {Scene::lateral_force_figures(scene),
                          Scene::floor_stress_figures(scene)})
        for (const auto &point : list)
          if (options.figure.empty() || point.figure == options.figure)
            figure_points.push_back(point);

      std::set<double> grid_curvatures, grid_loads;
      for (const auto &point : figure_points)
        {
          grid_curvatures.insert(point.curvature);
          grid_loads.insert(std::round(point.support_load /
                                       Units::tonnes_force_to_newtons(1.)));
        }
      const std::string figures =
        options.figure.empty() ? "the figures" : options.figure;
      for (const double curvature : options.curvatures)
        if (grid_curvatures.count(curvature) == 0)
          throw InputError("--curvatures",
                           fmt::format("{}", curvature),
                           "one of the k (m) of " + figures + ": " +
                             number_list(grid_curvatures) +
                             " (0 = planar bed)");
      if (!options.load_range.empty() &&
          !(options.load_range[0] <= options.load_range[1]))
        throw InputError("--loads",
                         fmt::format("{},{}",
                                     options.load_range[0],
                                     options.load_range[1]),
                         "MIN,MAX in tonnes with MIN <= MAX");

      std::vector<Scene::FigurePoint> points;
      for (const auto &point : figure_points)
        {
          const double tonnes =
            point.support_load / Units::tonnes_force_to_newtons(1.);
          const bool curvature_chosen =
            options.curvatures.empty() ||
            std::find(options.curvatures.begin(),
                      options.curvatures.end(),
                      point.curvature) != options.curvatures.end();
          // Half a tonne either side: the grid's loads are whole tonnes.
          const bool load_chosen = options.load_range.empty() ||
                                   (tonnes > options.load_range[0] - 0.5 &&
                                    tonnes < options.load_range[1] + 0.5);
          if (curvature_chosen && load_chosen)
            points.push_back(point);
        }
      if (points.empty())
        throw InputError("--loads",
                         fmt::format("{},{}",
                                     options.load_range[0],
                                     options.load_range[1]),
                         "a range holding a support load of the chosen "
                         "points: " +
                           number_list(grid_loads) + " t");
      return points;
    }

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
                         "one of fig6_5, fig6_6, fig6_7, fig6_10_11 (or "
                         "kn_safety, the floor's safety factor against kn)");
      const std::vector<Scene::FigurePoint> points =
        chosen_points(options, scene);

      const Output::ResultFolder folder(output_directory(options, scene));
      folder.write_inputs(scene);
      const unsigned int remaining =
        Pipeline::run_fem_sweep(points, folder, options.case_limit);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << points.size() - remaining << " of " << points.size()
                  << " chosen FEM cases finished; results in "
                  << output_directory(options, scene) << std::endl;
      return 0;
    }

    /**
     * `sweep --figure kn_safety`: the floor's safety factor against the
     * joints' kn (Studies::kn_safety_sweep()), its own FEM study; the
     * options that pick grid points of the chapter's figures do not apply.
     */
    int
    kn_safety_command(const CommandOptions                 &options,
                      const Parameters::ScenarioParameters &scene)
    {
      if (options.case_limit > 0 || !options.curvatures.empty() ||
          !options.load_range.empty())
        throw InputError("--figure kn_safety solves its seven cases whole: "
                         "leave out --limit, --curvatures and --loads, which "
                         "pick points of the chapter's figures");
      require_plane_scene(scene, "sweep --figure kn_safety");
      Studies::check_kn_safety_scene(scene);
      const Output::ResultFolder folder(output_directory(options, scene));
      folder.write_inputs(scene);
      const auto sweep =
        Studies::kn_safety_sweep(scene, folder, [](const std::string &line) {
          std::cout << line << std::endl;
        });
      Studies::write_kn_safety(folder, sweep);
      std::cout << "wrote " << folder.path_of("kn_safety.csv") << ", "
                << folder.path_of("kn_safety.png") << " (each solve under "
                << folder.path_of("kn_safety/") << ")" << std::endl;
      return exit_code::success;
    }

    /** Options that choose FEM cases do nothing without --fem. */
    void
    refuse_case_options_without_fem(const CommandOptions &options)
    {
      const std::vector<std::pair<std::string, bool>> given = {
        {"--figure", !options.figure.empty()},
        {"--limit", options.case_limit > 0},
        {"--curvatures", !options.curvatures.empty()},
        {"--loads", !options.load_range.empty()}};
      for (const auto &[name, present] : given)
        if (present)
          throw InputError(name +
                           " chooses the FEM cases of `sweep --fem` and "
                           "does nothing without --fem (the closed-form "
                           "sweep evaluates every point of every figure in "
                           "about a second): add --fem or leave " +
                           name + " out");
    }
  } // namespace

  int
  sweep_command(const CommandOptions &options)
  {
    const auto scene = read_scene(options);
    if (options.figure == "kn_safety")
      return kn_safety_command(options, scene);
    if (options.with_fem)
      {
        require_plane_scene(scene, "sweep --fem");
        return fem_sweep_command(options, scene);
      }
    refuse_case_options_without_fem(options);
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
