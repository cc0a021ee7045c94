#include <deal.II/grid/grid_tools_cache.h>

#include <safety/corner_sampling.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Safety
{
  std::vector<CornerSamplePoints>
  locate_corner_samples(const Parameters::ScenarioParameters &scene,
                        const Fem::FeSpace<2>                &space)
  {
    const double L = scene.strength.critical_distance;
    // The first sample sits a hair inside the block: at a sharp corner the
    // two blocks' meshes share the point, and the stress belongs to this
    // block's cell.
    const double hair = 1e-9 * scene.geometry.block_width;
    // One search structure for every point: building it costs the mesh.
    const dealii::GridTools::Cache<2> cache(
      space.dof_handler().get_triangulation(), space.mapping());
    std::vector<double> distances;
    for (unsigned int k = 0; k <= samples_per_critical_distance; ++k)
      distances.push_back(L * k / samples_per_critical_distance);
    const auto ray = [&](const Geometry::Point2 &start,
                         const Geometry::Point2 &direction) {
      std::vector<dealii::Point<2>> points;
      for (const double d : distances)
        {
          const double along = std::max(d, hair);
          points.emplace_back(start.x + along * direction.x,
                              start.y + along * direction.y);
        }
      return Fem::locate_points(cache, points);
    };

    std::vector<CornerSamplePoints> result;
    for (const CornerPath &path : floor_corner_paths(scene))
      {
        CornerSamplePoints corner;
        corner.path       = path;
        corner.distances  = distances;
        corner.along_path = ray(path.start, path.direction);
        for (unsigned int j = 0; j < rays_per_corner; ++j)
          {
            const double turn =
              (-0.25 + 0.5 * (j + 0.5) / rays_per_corner) * M_PI;
            const Geometry::Point2 direction{std::cos(turn) * path.direction.x -
                                               std::sin(turn) *
                                                 path.direction.y,
                                             std::sin(turn) * path.direction.x +
                                               std::cos(turn) *
                                                 path.direction.y};
            corner.rays.push_back(ray(path.start, direction));
          }
        result.push_back(corner);
      }
    return result;
  }
} // namespace FloorBlock::Safety
