#include <output/deformed_picture.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Output
{
  namespace
  {
    /** Displacement of every vertex of the mesh (m), by vertex index. */
    std::vector<dealii::Tensor<1, 2>>
    vertex_displacements(
      const dealii::DoFHandler<2>                 &dof_handler,
      const dealii::TrilinosWrappers::MPI::Vector &displacement)
    {
      std::vector<dealii::Tensor<1, 2>> result(
        dof_handler.get_triangulation().n_vertices());
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int component = 0; component < 2; ++component)
            result[cell->vertex_index(v)][component] =
              displacement(cell->vertex_dof_index(v, component));
      return result;
    }
  } // namespace

  double
  write_deformed_picture(
    const dealii::DoFHandler<2>                 &dof_handler,
    const dealii::TrilinosWrappers::MPI::Vector &displacement,
    const std::vector<PictureMarker>            &markers,
    const std::string                           &png_path,
    const double                                 magnification,
    const std::string                           &title)
  {
    const dealii::Triangulation<2> &reference = dof_handler.get_triangulation();
    const std::vector<dealii::Tensor<1, 2>> motion =
      vertex_displacements(dof_handler, displacement);
    const std::vector<dealii::Point<2>> &vertices = reference.get_vertices();
    const std::vector<bool>             &used = reference.get_used_vertices();

    double largest = 0., x_min = 1e300, x_max = -1e300;
    for (unsigned int i = 0; i < vertices.size(); ++i)
      if (used[i])
        {
          largest = std::max(largest, motion[i].norm());
          x_min   = std::min(x_min, vertices[i][0]);
          x_max   = std::max(x_max, vertices[i][0]);
        }
    constexpr double drawn_fraction_of_width = 0.1;
    const double     factor =
      magnification > 0. ? magnification :
          largest > 0. ? drawn_fraction_of_width * (x_max - x_min) / largest :
                         1.;

    dealii::Triangulation<2> deformed;
    deformed.copy_triangulation(reference);
    // Manifolds would pull refined points back onto the undeformed curves;
    // the picture needs only the moved vertices.
    deformed.reset_all_manifolds();
    for (const auto &cell : deformed.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        cell->vertex(v) = vertices[cell->vertex_index(v)] +
                          factor * motion[cell->vertex_index(v)];

    std::vector<PictureMarker> moved = markers;
    for (PictureMarker &marker : moved)
      {
        const unsigned int vertex =
          dealii::GridTools::find_closest_vertex(reference,
                                                 marker.position,
                                                 used);
        marker.position += factor * motion[vertex];
      }

    MeshPictureOptions options;
    options.title   = title + fmt::format("{}displacements x {:.3g}",
                                        title.empty() ? "" : ", ",
                                        factor);
    options.markers = std::move(moved);
    write_mesh_picture(deformed, png_path, options);
    return factor;
  }
} // namespace FloorBlock::Output
