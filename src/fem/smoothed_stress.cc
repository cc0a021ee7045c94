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
    , model(model)
    , displacement(displacement)
    , cache(space.dof_handler().get_triangulation(), space.mapping())
    // The trapezoidal rule's points are the cell's vertices, in deal.II's
    // vertex order.
    , at_vertices(space.mapping(),
                  space.fe(),
                  dealii::QTrapezoid<2>(),
                  dealii::update_gradients)
  {}

  const PointStress &
  SmoothedStress::vertex_mean(const unsigned int               vertex,
                              const dealii::types::material_id material) const
  {
    const auto known = vertex_means.find({vertex, material});
    if (known != vertex_means.end())
      return known->second;
    const dealii::FEValuesExtractors::Vector displacements(0);
    std::vector<dealii::Tensor<2, 2>>        gradients(
      at_vertices.n_quadrature_points);
    const Material::ElasticLaw<2> &law = model.laws.at(material);
    PointStress                    sum;
    unsigned int                   count = 0;
    // The map also lists coarser neighbours on whose face a hanging vertex
    // lies: only cells that have the vertex as one of theirs count.
    for (const auto &cell : cache.get_vertex_to_cell_map()[vertex])
      for (unsigned int v = 0; v < cell->n_vertices(); ++v)
        if (cell->vertex_index(v) == vertex && cell->material_id() == material)
          {
            const dealii::DoFHandler<2>::active_cell_iterator dof_cell(
              &cell->get_triangulation(),
              cell->level(),
              cell->index(),
              &space.dof_handler());
            at_vertices.reinit(dof_cell);
            at_vertices[displacements].get_function_gradients(displacement,
                                                              gradients);
            const auto strain = dealii::symmetrize(gradients[v]);
            sum.in_plane += law.stress(strain);
            sum.out_of_plane += law.out_of_plane_stress(strain);
            ++count;
          }
    sum.in_plane /= count;
    sum.out_of_plane /= count;
    return vertex_means.emplace(std::make_pair(vertex, material), sum)
      .first->second;
  }

  std::vector<PointLocation>
  locate_points(const dealii::GridTools::Cache<2>   &cache,
                const std::vector<dealii::Point<2>> &points)
  {
    std::vector<PointLocation> result;
    // Points along a path: the last point's cell is the best first guess.
    dealii::Triangulation<2>::active_cell_iterator hint;
    for (const dealii::Point<2> &point : points)
      {
        const auto [cell, reference] =
          dealii::GridTools::find_active_cell_around_point(cache, point, hint);
        if (cell.state() != dealii::IteratorState::valid)
          throw std::invalid_argument(
            "SmoothedStress: the point (" + std::to_string(point[0]) + ", " +
            std::to_string(point[1]) + ") lies outside the mesh");
        hint = cell;
        result.push_back({cell, reference});
      }
    return result;
  }

  std::vector<PointStress>
  SmoothedStress::at(const std::vector<dealii::Point<2>> &points) const
  {
    return at(locate_points(cache, points));
  }

  std::vector<PointStress>
  SmoothedStress::at(const std::vector<PointLocation> &locations) const
  {
    std::vector<PointStress> result;
    for (const PointLocation &location : locations)
      {
        const auto &cell = location.cell;
        PointStress stress;
        stress.cell_size = cell->diameter() / std::sqrt(2.);
        // Bilinear weights of the four vertices (deal.II order: (0,0),
        // (1,0), (0,1), (1,1) in reference coordinates).
        const double x = location.reference[0], y = location.reference[1];
        const double weights[4] = {(1 - x) * (1 - y),
                                   x * (1 - y),
                                   (1 - x) * y,
                                   x * y};
        for (unsigned int v = 0; v < 4; ++v)
          {
            const PointStress &vertex =
              vertex_mean(cell->vertex_index(v), cell->material_id());
            stress.in_plane += weights[v] * vertex.in_plane;
            stress.out_of_plane += weights[v] * vertex.out_of_plane;
          }
        result.push_back(stress);
      }
    return result;
  }
} // namespace FloorBlock::Fem
