#include <fem/smoothed_stress.h>
#include <safety/corner_safety.h>

#include <algorithm>
#include <stdexcept>

namespace FloorBlock::Safety
{
  Strength::PlaneStrainStress
  plane_strain(const Fem::PointStress &stress)
  {
    return {stress.in_plane[0][0],
            stress.in_plane[1][1],
            stress.in_plane[0][1],
            stress.out_of_plane};
  }

  std::vector<CornerSafety>
  corner_safety(const Parameters::ScenarioParameters        &scene,
                const Fem::FeSpace<2>                       &space,
                const Fem::ElasticModel<2>                  &model,
                const dealii::TrilinosWrappers::MPI::Vector &solution)
  {
    const double L         = scene.strength.critical_distance;
    const double sigma_ci  = scene.strength.intact_ucs;
    const auto   constants = scene.strength.hoek_brown();
    // The first sample sits a hair inside the block: at a sharp corner the
    // two blocks' meshes share the point, and the stress belongs to this
    // block's cell.
    const double hair = 1e-9 * scene.geometry.block_width;

    const Fem::SmoothedStress field(space, model, solution);
    std::vector<CornerSafety> result;
    for (const CornerPath &path : floor_corner_paths(scene))
      {
        std::vector<dealii::Point<2>> points;
        std::vector<double>           distances;
        for (unsigned int k = 0; k <= samples_per_critical_distance; ++k)
          {
            const double d = L * k / samples_per_critical_distance;
            const double along = std::max(d, hair);
            distances.push_back(d);
            points.emplace_back(path.start.x + along * path.direction.x,
                                path.start.y + along * path.direction.y);
          }
        const std::vector<Fem::PointStress> stresses = field.at(points);
        std::vector<Strength::PathSample> samples;
        CornerSafety                      corner;
        for (std::size_t k = 0; k < stresses.size(); ++k)
          {
            samples.push_back({distances[k], plane_strain(stresses[k])});
            corner.largest_cell =
              std::max(corner.largest_cell, stresses[k].cell_size);
          }

        corner.samples           = samples;
        corner.path              = path;
        corner.critical_distance = L;
        corner.point_stresses    = Strength::principal_stresses(
          Strength::point_method_stress(samples, L));
        corner.line_stresses = Strength::principal_stresses(
          Strength::line_method_stress(samples, L));
        corner.point_factor =
          Strength::strength_factor(corner.point_stresses, sigma_ci, constants);
        corner.line_factor =
          Strength::strength_factor(corner.line_stresses, sigma_ci, constants);
        // The factor along the path, for floor_safety_paths.csv: only
        // where the path is resolved (elsewhere it is not written).
        if (corner.resolved())
          for (const Strength::PathSample &sample : corner.samples)
            corner.sample_factors.push_back(Strength::strength_factor(
              Strength::principal_stresses(sample.stress), sigma_ci, constants));
        result.push_back(corner);
      }
    return result;
  }

  bool
  CornerSafety::resolved() const
  {
    return largest_cell <=
           critical_distance / min_cells_per_critical_distance * (1. + 1e-9);
  }

  double
  verdict_factor(const CornerSafety &corner)
  {
    return corner.line_factor;
  }

  const CornerSafety &
  governing_corner(const std::vector<CornerSafety> &corners)
  {
    if (corners.empty())
      throw std::logic_error("governing_corner: no corners");
    // Any unresolved corner governs, the one with the largest cells: a
    // corner whose factor is a cell's value may be the weakest, so no
    // verdict can be given for the floor; else the smallest factor.
    return *std::min_element(corners.begin(),
                             corners.end(),
                             [](const CornerSafety &a, const CornerSafety &b) {
                               if (a.resolved() != b.resolved())
                                 return !a.resolved();
                               if (!a.resolved())
                                 return a.largest_cell > b.largest_cell;
                               return verdict_factor(a) < verdict_factor(b);
                             });
  }
} // namespace FloorBlock::Safety
