#include <fem/point_stress.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>

namespace FloorBlock::Fem
{
  std::vector<PointStress>
  stresses_at_points(const FeSpace<2>                            &space,
                     const ElasticModel<2>                       &model,
                     const dealii::TrilinosWrappers::MPI::Vector &displacement,
                     const std::vector<dealii::Point<2>>         &points)
  {
    const dealii::FEValuesExtractors::Vector displacements(0);
    std::vector<dealii::Tensor<2, 2>>        gradient(1);
    std::vector<PointStress>                 result;
    result.reserve(points.size());
    for (const dealii::Point<2> &point : points)
      {
        const auto [cell, reference] =
          dealii::GridTools::find_active_cell_around_point(space.mapping(),
                                                           space.dof_handler(),
                                                           point);
        // A one-point rule at the point's reference coordinates.
        const dealii::Quadrature<2> at_point(reference);
        dealii::FEValues<2>         fe_values(space.mapping(),
                                      space.fe(),
                                      at_point,
                                      dealii::update_gradients);
        fe_values.reinit(cell);
        fe_values[displacements].get_function_gradients(displacement,
                                                        gradient);
        const Material::ElasticLaw<2> &law = model.laws.at(cell->material_id());
        const dealii::SymmetricTensor<2, 2> strain =
          dealii::symmetrize(gradient[0]);
        result.push_back({law.stress(strain),
                          law.out_of_plane_stress(strain),
                          cell->diameter() / std::sqrt(2.)});
      }
    return result;
  }
} // namespace FloorBlock::Fem
