#include <output/gnuplot.h>
#include <output/strength_factor_picture.h>
#include <pipeline/strength_factor_view.h>
#include <safety/corner_paths.h>
#include <safety/strength_factor_field.h>

#include <algorithm>

namespace FloorBlock::Pipeline
{
  void
  write_strength_factor_view(const Parameters::ScenarioParameters &scene,
                             const Contact::ContactSolver<2>      &solver,
                             const Fem::ElasticModel<2>           &model,
                             const std::string                    &png_path)
  {
    if (solver.responses_at_solution().size() != solver.contact_nodes().size())
      return; // nothing converged: no state to draw
    const std::vector<Safety::CornerPath> paths =
      Safety::floor_corner_paths(scene);
    const auto face = std::find_if(paths.begin(),
                                   paths.end(),
                                   [](const Safety::CornerPath &path) {
                                     return path.block == "face block";
                                   });
    if (face == paths.end())
      return;
    // Ten critical distances show the overstressed zone and the path
    // together; never more than half a block, which holds the next corner.
    const double L          = scene.strength.critical_distance;
    const double half_width = std::min(
      10. * L,
      0.5 * std::min(scene.geometry.block_width, scene.geometry.block_height));
    constexpr unsigned int n_points_across = 61;
    const Safety::StrengthFactorMap map =
      Safety::strength_factor_map(scene,
                                  solver.space(),
                                  model,
                                  solver.solution(),
                                  *face,
                                  half_width,
                                  n_points_across);
    Output::render_png(Output::strength_factor_plot(map, L), png_path, 900, 560);
  }
} // namespace FloorBlock::Pipeline
