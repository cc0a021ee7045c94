#include <fem/cell_stress.h>
#include <fem/smoothed_stress.h>
#include <safety/corner_safety.h>
#include <safety/strength_factor_field.h>

#include <stdexcept>

namespace FloorBlock::Safety
{
  namespace
  {
    double
    factor_of(const Fem::PointStress               &stress,
              const Parameters::ScenarioParameters &scene)
    {
      return Strength::strength_factor(
        Strength::principal_stresses(plane_strain(stress)),
        scene.strength.intact_ucs,
        scene.strength.hoek_brown());
    }
  } // namespace

  std::vector<double>
  cell_strength_factors(const Parameters::ScenarioParameters        &scene,
                        const Fem::FeSpace<2>                       &space,
                        const Fem::ElasticModel<2>                  &model,
                        const dealii::TrilinosWrappers::MPI::Vector &solution)
  {
    std::vector<double> result;
    for (const Fem::PointStress &stress :
         Fem::cell_centre_stresses(space, model, solution))
      result.push_back(factor_of(stress, scene));
    return result;
  }

  StrengthFactorMap
  strength_factor_map(const Parameters::ScenarioParameters        &scene,
                      const Fem::FeSpace<2>                       &space,
                      const Fem::ElasticModel<2>                  &model,
                      const dealii::TrilinosWrappers::MPI::Vector &solution,
                      const CornerPath                            &corner,
                      const double                                 half_width,
                      const unsigned int                           n_x)
  {
    StrengthFactorMap map;
    map.corner  = corner;
    map.n_x     = n_x;
    map.n_y     = n_x / 2 + 1;
    map.spacing = 2. * half_width / (n_x - 1);
    map.x_min   = corner.start.x - half_width;
    map.y_min   = corner.start.y - half_width;
    const Fem::SmoothedStress field(space, model, solution);
    for (unsigned int j = 0; j < map.n_y; ++j)
      for (unsigned int i = 0; i < map.n_x; ++i)
        {
          const dealii::Point<2> point(map.x_min + i * map.spacing,
                                       map.y_min + j * map.spacing);
          try
            {
              map.factors.push_back(
                factor_of(field.at({point}).front(), scene));
            }
          catch (const std::exception &)
            {
              // Outside the blocks: above the floor or in a fillet's gap.
              map.factors.push_back(std::nullopt);
            }
        }
    return map;
  }
} // namespace FloorBlock::Safety
