#include <corner/side_mean_pressure.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>


namespace FloorBlock::Corner
{
  std::vector<FaceValue>
  mean_pressure_on_side(const Fem::FeSpace<2>                       &space,
                        const dealii::TrilinosWrappers::MPI::Vector &solution,
                        const dealii::types::boundary_id             side,
                        const Material::ElasticLaw<2>               &law)
  {
    const dealii::Quadrature<2>              centre(dealii::Point<2>(0.5, 0.5));
    dealii::FEValues<2>                      values(space.mapping(),
                               space.fe(),
                               centre,
                               dealii::update_gradients);
    const dealii::FEValuesExtractors::Vector displacement(0);
    std::vector<dealii::SymmetricTensor<2, 2>> strain(1);
    std::vector<FaceValue>                     result;
    for (const auto &cell : space.dof_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == side)
          {
            values.reinit(cell);
            values[displacement].get_function_symmetric_gradients(solution,
                                                                  strain);
            const double trace = dealii::trace(law.stress(strain[0])) +
                                 law.out_of_plane_stress(strain[0]);
            result.push_back({cell->face(f)->vertex(0),
                              cell->face(f)->vertex(1),
                              -trace / 3.});
          }
    return result;
  }
} // namespace FloorBlock::Corner
