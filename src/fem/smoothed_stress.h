#pragma once

#include <fem/elastic_model.h>
#include <fem/fe_space.h>
#include <fem/point_stress.h>

#include <deal.II/base/point.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/lac/trilinos_vector.h>

#include <map>
#include <utility>
#include <vector>

namespace FloorBlock::Fem
{
  /**
   * @brief A continuous stress field per body from the displacement
   * solution: at every mesh vertex the mean over the body's cells that
   * share it of their stress at that vertex (nodal averaging), and between
   * vertices the bilinear interpolant of the cell's four vertex values.
   *
   * Why: the stress of a displacement FE field jumps between cells by
   * about h |grad sigma|, so a stress read at one point is the value of
   * whichever cell holds it. Averaging at the vertices removes the jumps
   * (and is of higher order than either cell's value there); each body
   * is averaged on its own, since the stress is discontinuous across a
   * joint. The vertex means are computed when a point first needs them,
   * so reading a few paths costs the cells around them, not the mesh.
   * One process; four-vertex cells.
   */
  /** @brief A point's cell and its coordinates in the reference cell:
   * where a point lies in a mesh, found once and read at any solution on
   * that mesh. */
  struct PointLocation
  {
    dealii::Triangulation<2>::active_cell_iterator cell;
    dealii::Point<2>                               reference;
  };

  /**
   * @brief The cells of @p points in @p cache's mesh, each search starting
   * from the last point's cell (points along a path). Locating is most of
   * the cost of reading a few paths, and it does not depend on the
   * solution: a load path on one mesh locates its points once.
   * @throws std::invalid_argument for a point outside the mesh.
   */
  std::vector<PointLocation>
  locate_points(const dealii::GridTools::Cache<2>   &cache,
                const std::vector<dealii::Point<2>> &points);

  class SmoothedStress
  {
  public:
    SmoothedStress(const FeSpace<2>                            &space,
                   const ElasticModel<2>                       &model,
                   const dealii::TrilinosWrappers::MPI::Vector &displacement);

    /** @brief The smoothed stress at @p points (cell_size as
     * stresses_at_points()). Throws std::invalid_argument outside the
     * mesh. */
    std::vector<PointStress>
    at(const std::vector<dealii::Point<2>> &points) const;

    /** @brief The smoothed stress at points located in this mesh. */
    std::vector<PointStress>
    at(const std::vector<PointLocation> &locations) const;

  private:
    /** @brief The mean stress at @p vertex over the cells of material
     * @p material that have it as a vertex (memoized). */
    const PointStress &
    vertex_mean(unsigned int vertex, dealii::types::material_id material) const;

    const FeSpace<2>                            &space;
    const ElasticModel<2>                       &model;
    const dealii::TrilinosWrappers::MPI::Vector &displacement;
    /** Vertex-to-cell maps for finding the cells of many points fast. */
    dealii::GridTools::Cache<2> cache;
    /** Displacement gradients at a cell's vertices, built once: a region
     * of a few thousand vertices would otherwise build one per vertex. */
    mutable dealii::FEValues<2> at_vertices;
    /** (vertex index, material id) -> mean stress, filled on demand. */
    mutable std::map<std::pair<unsigned int, dealii::types::material_id>,
                     PointStress>
      vertex_means;
  };
} // namespace FloorBlock::Fem
