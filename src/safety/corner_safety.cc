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
    return corner_safety(
      scene, locate_corner_samples(scene, space), space, model, solution);
  }

  std::vector<CornerSafety>
  corner_safety(const Parameters::ScenarioParameters        &scene,
                const std::vector<CornerSamplePoints>       &sample_points,
                const Fem::FeSpace<2>                       &space,
                const Fem::ElasticModel<2>                  &model,
                const dealii::TrilinosWrappers::MPI::Vector &solution)
  {
    const double L         = scene.strength.critical_distance;
    const double sigma_ci  = scene.strength.intact_ucs;
    const auto   constants = scene.strength.hoek_brown();

    const Fem::SmoothedStress field(space, model, solution);
    // The stress at @p located points over [0, L] (at @p distances), and
    // the largest cell they lie in.
    const auto read = [&](const std::vector<double>             &distances,
                          const std::vector<Fem::PointLocation> &located,
                          double                                &largest_cell) {
      const std::vector<Fem::PointStress> stresses = field.at(located);
      std::vector<Strength::PathSample>   samples;
      for (std::size_t k = 0; k < stresses.size(); ++k)
        {
          samples.push_back({distances[k], plane_strain(stresses[k])});
          largest_cell = std::max(largest_cell, stresses[k].cell_size);
        }
      return samples;
    };

    std::vector<CornerSafety> result;
    for (const CornerSamplePoints &points : sample_points)
      {
        const CornerPath &path = points.path;
        CornerSafety      corner;
        corner.samples =
          read(points.distances, points.along_path, corner.largest_cell);
        std::vector<std::vector<Strength::PathSample>> rays;
        for (const auto &ray : points.rays)
          rays.push_back(
            read(points.distances, ray, corner.largest_cell_within_L));

        corner.path              = path;
        corner.critical_distance = L;
        corner.point_stresses    = Strength::principal_stresses(
          Strength::point_method_stress(corner.samples, L));
        corner.line_stresses = Strength::principal_stresses(
          Strength::line_method_stress(corner.samples, L));
        corner.area_stresses =
          Strength::principal_stresses(Strength::area_method_stress(rays, L));
        corner.point_factor =
          Strength::strength_factor(corner.point_stresses, sigma_ci, constants);
        corner.line_factor =
          Strength::strength_factor(corner.line_stresses, sigma_ci, constants);
        corner.area_factor =
          Strength::strength_factor(corner.area_stresses, sigma_ci, constants);
        corner.verdict_method = verdict_method(scene.joints.law);
        // The factor along the path, for floor_safety_paths.csv: only
        // where the path is resolved (elsewhere it is not written).
        if (corner.resolved())
          for (const Strength::PathSample &sample : corner.samples)
            corner.sample_factors.push_back(Strength::strength_factor(
              Strength::principal_stresses(sample.stress),
              sigma_ci,
              constants));
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

  const char *
  to_string(const SafetyMethod method)
  {
    switch (method)
      {
        case SafetyMethod::point:
          return "point";
        case SafetyMethod::line:
          return "line";
        case SafetyMethod::area:
          return "area";
      }
    return "unknown";
  }

  SafetyMethod
  verdict_method(const Contact::JointLawKind law)
  {
    return law == Contact::JointLawKind::rigid ? SafetyMethod::area :
                                                 SafetyMethod::line;
  }

  double
  factor(const CornerSafety &corner, const SafetyMethod method)
  {
    switch (method)
      {
        case SafetyMethod::point:
          return corner.point_factor;
        case SafetyMethod::line:
          return corner.line_factor;
        case SafetyMethod::area:
          return corner.area_factor;
      }
    throw std::logic_error("factor: unknown method");
  }

  double
  verdict_factor(const CornerSafety &corner)
  {
    return factor(corner, corner.verdict_method);
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
