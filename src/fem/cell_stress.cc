#include <fem/cell_stress.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Fem
{
  std::vector<PointStress>
  cell_centre_stresses(const FeSpace<2>                            &space,
                       const ElasticModel<2>                       &model,
                       const dealii::TrilinosWrappers::MPI::Vector &displacement)
  {
    const auto &dof_handler = space.dof_handler();
    // One point at the cell centre: a picture needs one value per cell.
    const dealii::QGauss<2>                  centre(1);
    dealii::FEValues<2>                      fe_values(space.mapping(),
                                  space.fe(),
                                  centre,
                                  dealii::update_gradients);
    const dealii::FEValuesExtractors::Vector displacements(0);
    std::vector<dealii::Tensor<2, 2>>        gradients(1);
    std::vector<PointStress>                 result(
      dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacements].get_function_gradients(displacement,
                                                          gradients);
          const Material::ElasticLaw<2> &law =
            model.laws.at(cell->material_id());
          const dealii::SymmetricTensor<2, 2> strain =
            dealii::symmetrize(gradients[0]);
          PointStress &entry = result[cell->active_cell_index()];
          entry.in_plane     = law.stress(strain);
          entry.out_of_plane = law.out_of_plane_stress(strain);
          entry.cell_size    = cell->diameter() / std::sqrt(2.);
        }
    return result;
  }

  std::vector<double>
  cell_major_compressive_stress(
    const FeSpace<2>                            &space,
    const ElasticModel<2>                       &model,
    const dealii::TrilinosWrappers::MPI::Vector &displacement)
  {
    std::vector<double> result;
    for (const PointStress &entry :
         cell_centre_stresses(space, model, displacement))
      {
        const auto  &stress           = entry.in_plane;
        const double centre_of_circle = (stress[0][0] + stress[1][1]) / 2.;
        const double radius =
          std::hypot((stress[0][0] - stress[1][1]) / 2., stress[0][1]);
        // Tension positive in the law; the most compressive of the three
        // principal stresses, sign turned.
        result.push_back(-std::min(centre_of_circle - radius, entry.out_of_plane));
      }
    return result;
  }
} // namespace FloorBlock::Fem
