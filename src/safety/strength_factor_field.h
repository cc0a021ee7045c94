#pragma once

#include <fem/elastic_model.h>
#include <fem/fe_space.h>
#include <parameters/scenario_parameters.h>
#include <safety/corner_paths.h>

#include <deal.II/lac/trilinos_vector.h>

#include <optional>
#include <vector>

namespace FloorBlock::Safety
{
  /**
   * @brief The Hoek-Brown strength factor (Strength::strength_factor(),
   * Strength/ of @p scene) of every active cell's stress at its centre,
   * by active_cell_index(): the field ParaView shows. A cell's value, not
   * the smoothed field's: a picture of where the rock is overstressed,
   * not a figure (those are the corner factors, corner_safety()).
   */
  std::vector<double>
  cell_strength_factors(const Parameters::ScenarioParameters        &scene,
                        const Fem::FeSpace<2>                       &space,
                        const Fem::ElasticModel<2>                  &model,
                        const dealii::TrilinosWrappers::MPI::Vector &solution);

  /** The strength factor on a regular grid of points around a corner. */
  struct StrengthFactorMap
  {
    CornerPath   corner;
    double       x_min = 0., y_min = 0.; ///< lower left point (m)
    double       spacing = 0.;           ///< between grid points (m)
    unsigned int n_x = 0, n_y = 0;
    /** Row by row from y_min; none outside the blocks (above the floor,
     * in a joint's fillet gap). */
    std::vector<std::optional<double>> factors;
  };

  /**
   * @brief The strength factor of the smoothed stress (Fem::SmoothedStress)
   * on an @p n_x by n_x / 2 grid spanning @p half_width either side of
   * @p corner's surface point and @p half_width below the floor: the
   * picture strength_factor.png draws with its FS = 1 contour.
   */
  StrengthFactorMap
  strength_factor_map(const Parameters::ScenarioParameters        &scene,
                      const Fem::FeSpace<2>                       &space,
                      const Fem::ElasticModel<2>                  &model,
                      const dealii::TrilinosWrappers::MPI::Vector &solution,
                      const CornerPath                            &corner,
                      double                                       half_width,
                      unsigned int                                 n_x);
} // namespace FloorBlock::Safety
