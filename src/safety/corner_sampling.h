#pragma once

#include <fem/fe_space.h>
#include <fem/smoothed_stress.h>
#include <parameters/scenario_parameters.h>

#include <safety/corner_paths.h>

#include <vector>

namespace FloorBlock::Safety
{
  /** Samples of the stress along [0, L] of each path: the FE field is
   * smooth within cells, so this many points resolve cells down to L/32
   * with linear interpolation between them. */
  constexpr unsigned int samples_per_critical_distance = 128;

  /** Rays at equal angles across the block's right-angled corner for the
   * area method (the midpoint rule in angle: for a field varying as
   * cos(2 theta) its error is 0.2 % of the amplitude). */
  constexpr unsigned int rays_per_corner = 16;

  /** @brief Where one corner's samples lie: its path and the area
   * method's rays, each over [0, L]. */
  struct CornerSamplePoints
  {
    CornerPath                                   path;
    std::vector<double>                          distances; ///< m, per ray
    std::vector<Fem::PointLocation>              along_path;
    std::vector<std::vector<Fem::PointLocation>> rays;
  };

  /**
   * @brief The sample points of every floor-level corner
   * (floor_corner_paths()) located in @p space's mesh. Locating them is
   * most of the cost of reading the corners, and it depends on the mesh
   * alone: a load path locates them once and reads them at every
   * increment (corner_safety()).
   *
   * The area method's rays cover the block's material within L of the
   * hot spot: the quarter disc between its two faces, the path's bisector
   * +- 45 degrees (with a fillet too: the quarter disc at the fillet's
   * middle lies inside it).
   */
  std::vector<CornerSamplePoints>
  locate_corner_samples(const Parameters::ScenarioParameters &scene,
                        const Fem::FeSpace<2>                &space);
} // namespace FloorBlock::Safety
