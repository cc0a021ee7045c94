#include <fem/smoothed_stress.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace FloorBlock::Fem
{
  SmoothedStress::SmoothedStress(
    const FeSpace<2>                            &space,
    const ElasticModel<2>                       &model,
    const dealii::TrilinosWrappers::MPI::Vector &displacement)
    : space(space)
    , cache(space.dof_handler().get_triangulation(), space.mapping())
  {
    // The trapezoidal rule's points are the cell's vertices, in deal.II's
    // vertex order.
    const dealii::QTrapezoid<2>              at_vertices;
    dealii::FEValues<2>                      fe_values(space.mapping(),
                                  space.fe(),
                                  at_vertices,
                                  dealii::update_gradients);
    const dealii::FEValuesExtractors::Vector displacements(0);
    std::vector<dealii::Tensor<2, 2>>        gradients(at_vertices.size());
    for (const auto &cell : space.dof_handler().active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[displacements].get_function_gradients(displacement,
                                                        gradients);
        const Material::ElasticLaw<2> &law = model.laws.at(cell->material_id());
        for (unsigned int v = 0; v < cell->n_vertices(); ++v)
          {
            const auto strain = dealii::symmetrize(gradients[v]);
            auto &[sum, count] =
              vertex_stress[{cell->vertex_index(v), cell->material_id()}];
            sum.in_plane += law.stress(strain);
            sum.out_of_plane += law.out_of_plane_stress(strain);
            ++count;
          }
      }
    for (auto &[key, entry] : vertex_stress)
      {
        entry.first.in_plane /= entry.second;
        entry.first.out_of_plane /= entry.second;
      }
  }

  std::vector<PointStress>
  SmoothedStress::at(const std::vector<dealii::Point<2>> &points) const
  {
    std::vector<PointStress> result;
    // Points along a path: the last point's cell is the best first guess.
    dealii::Triangulation<2>::active_cell_iterator hint;
    for (const dealii::Point<2> &point : points)
      {
        const auto [cell, reference] =
          dealii::GridTools::find_active_cell_around_point(cache, point, hint);
        if (cell.state() != dealii::IteratorState::valid)
          throw std::invalid_argument("SmoothedStress: the point (" +
                                      std::to_string(point[0]) + ", " +
                                      std::to_string(point[1]) +
                                      ") lies outside the mesh");
        hint = cell;
        PointStress stress;
        stress.cell_size = cell->diameter() / std::sqrt(2.);
        // Bilinear weights of the four vertices (deal.II order: (0,0),
        // (1,0), (0,1), (1,1) in reference coordinates).
        const double x = reference[0], y = reference[1];
        const double weights[4] = {(1 - x) * (1 - y),
                                   x * (1 - y),
                                   (1 - x) * y,
                                   x * y};
        for (unsigned int v = 0; v < 4; ++v)
          {
            const PointStress &vertex =
              vertex_stress.at({cell->vertex_index(v), cell->material_id()})
                .first;
            stress.in_plane += weights[v] * vertex.in_plane;
            stress.out_of_plane += weights[v] * vertex.out_of_plane;
          }
        result.push_back(stress);
      }
    return result;
  }
} // namespace FloorBlock::Fem
