#include <common/units.h>
#include <geometry/ids.h>
#include <output/deformed_picture.h>
#include <output/gnuplot.h>

#include <deal.II/grid/grid_tools.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

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

    /** Where the picture draws a point: displaced, then mirrored in x. */
    struct PicturePlacement
    {
      const std::vector<dealii::Point<2>>     &vertices;
      const std::vector<dealii::Tensor<1, 2>> &motion;
      double                                   factor;

      dealii::Point<2>
      operator()(const unsigned int vertex) const
      {
        return mirrored(vertices[vertex] + factor * motion[vertex]);
      }

      static dealii::Point<2>
      mirrored(const dealii::Point<2> &point)
      {
        return {-point[0], point[1]};
      }
    };

    /** Joint sides or floor surface as separate, drawn segments. */
    template <typename Predicate>
    std::string
    drawn_segments(const dealii::Triangulation<2> &reference,
                   const PicturePlacement         &place,
                   const Predicate                &wanted)
    {
      std::string text;
      for (const auto &cell : reference.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && wanted(face->boundary_id()))
            {
              const dealii::Point<2> from = place(face->vertex_index(0));
              const dealii::Point<2> to   = place(face->vertex_index(1));
              text +=
                fmt::format("{} {}\n{} {}\n\n", from[0], from[1], to[0], to[1]);
            }
      // gnuplot refuses an empty data block; a lone NaN point draws nothing.
      return text.empty() ? std::string("NaN NaN\n") : text;
    }

    /**
     * Tick marks of the mirrored x axis, labelled with the true x: about a
     * dozen ticks at a whole number of metres.
     */
    std::string
    true_x_tics(const double picture_x_min, const double picture_x_max)
    {
      constexpr double n_ticks_wanted = 12.;
      const double     step =
        std::max(1.,
                 std::ceil((picture_x_max - picture_x_min) / n_ticks_wanted));
      std::string tics;
      for (double x = std::ceil(picture_x_min / step) * step;
           x <= picture_x_max;
           x += step)
        tics += fmt::format("{}'{:g}' {:g}",
                            tics.empty() ? "" : ", ",
                            x == 0. ? 0. : -x,
                            x);
      return "set xtics (" + tics + ")\n";
    }

    /**
     * The cells as closed polygons with their stress (gnuplot data), the
     * blocks apart from the base, with the drawing's extent and the
     * blocks' peak stress (MPa).
     */
    struct CellPolygons
    {
      std::string blocks;
      std::string base;
      double      x_min = std::numeric_limits<double>::max();
      double      x_max = -std::numeric_limits<double>::max();
      double      y_min = std::numeric_limits<double>::max();
      double      y_max = -std::numeric_limits<double>::max();
      double      peak  = 0.;
    };

    CellPolygons
    cell_polygons(const dealii::Triangulation<2> &reference,
                  const PicturePlacement         &place,
                  const std::vector<double>      &cell_stress)
    {
      CellPolygons polygons;
      // deal.II vertex order is lexicographic; this visits them around the
      // cell.
      constexpr std::array<unsigned int, 5> around{{0, 1, 3, 2, 0}};
      // The base is bent into the bedding's shape by a prescribed uplift;
      // its bending stresses would set the colour scale and wash out the
      // blocks', so it is drawn in one colour and the scale is the blocks'
      // own.
      for (const auto &cell : reference.active_cell_iterators())
        {
          const bool in_base =
            cell->material_id() == Geometry::Ids::base_material;
          std::string &text = in_base ? polygons.base : polygons.blocks;
          const double stress =
            cell_stress[cell->active_cell_index()] / Units::MPa;
          if (!in_base)
            polygons.peak = std::max(polygons.peak, stress);
          for (const unsigned int v : around)
            {
              const dealii::Point<2> point = place(cell->vertex_index(v));
              polygons.x_min               = std::min(polygons.x_min, point[0]);
              polygons.x_max               = std::max(polygons.x_max, point[0]);
              polygons.y_min               = std::min(polygons.y_min, point[1]);
              polygons.y_max               = std::max(polygons.y_max, point[1]);
              text += fmt::format("{} {} {}\n", point[0], point[1], stress);
            }
          text += "\n";
        }
      return polygons;
    }

    /**
     * The markers' data blocks (appended to @p data) and their plot
     * clauses, one per category, at the deformed nodes nearest them.
     */
    std::string
    marker_clauses(const dealii::Triangulation<2>          &reference,
                   const std::vector<dealii::Tensor<1, 2>> &vertex_motion,
                   const std::vector<PictureMarker>        &markers,
                   const double                             factor,
                   std::string                             &data)
    {
      std::map<std::string, std::string> marker_points;
      const std::vector<bool>           &used = reference.get_used_vertices();
      for (const PictureMarker &marker : markers)
        {
          const unsigned int vertex =
            dealii::GridTools::find_closest_vertex(reference,
                                                   marker.position,
                                                   used);
          const dealii::Point<2> point = PicturePlacement::mirrored(
            marker.position + factor * vertex_motion[vertex]);
          marker_points[marker.category] +=
            fmt::format("{} {}\n", point[0], point[1]);
        }
      std::string  plot;
      unsigned int marker_index = 0;
      for (const auto &[category, points] : marker_points)
        {
          const std::string name = "$markers" + std::to_string(marker_index);
          data += name + " << EOD\n" + points + "EOD\n";
          // Small points: the joint nodes crowd at the corners, where the
          // stress colours matter most.
          plot += fmt::format(
            ", \\\n     {} with points pt 7 ps 0.35 lc rgb '{}' title {}",
            name,
            marker_colour(category, marker_index),
            gnuplot_string(category));
          ++marker_index;
        }
      return plot;
    }
  } // namespace

  std::string
  deformed_picture_script(
    const dealii::Triangulation<2>          &reference,
    const std::vector<dealii::Tensor<1, 2>> &vertex_motion,
    const std::vector<double>               &cell_stress,
    const std::vector<PictureMarker>        &markers,
    const double                             factor,
    const std::string                       &title)
  {
    const PicturePlacement place{reference.get_vertices(),
                                 vertex_motion,
                                 factor};
    namespace Ids               = Geometry::Ids;
    const CellPolygons polygons = cell_polygons(reference, place, cell_stress);
    const double       x_min = polygons.x_min, x_max = polygons.x_max;
    const double       y_min = polygons.y_min, y_max = polygons.y_max;
    const double       peak  = polygons.peak;
    const std::string &cells = polygons.blocks, &base = polygons.base;

    std::string data = "$cells << EOD\n" + cells + "EOD\n$base << EOD\n" +
                       (base.empty() ? std::string("NaN NaN NaN\n") : base) +
                       "EOD\n";
    data += "$joints << EOD\n" +
            drawn_segments(reference, place, Ids::is_joint_side) + "EOD\n";
    data += "$floor << EOD\n" +
            drawn_segments(reference,
                           place,
                           [](const dealii::types::boundary_id id) {
                             return Ids::boundary_kind(id) ==
                                    Ids::BoundaryKind::floor_surface;
                           }) +
            "EOD\n";
    std::string plot =
      "plot $base using 1:2 with filledcurves closed fc rgb '#e3cf9a' "
      "notitle, \\\n     $cells using 1:2:3 with filledcurves closed fc "
      "palette notitle, "
      "\\\n     $joints with lines lc rgb '#202020' lw 1.5 notitle, "
      "\\\n     $floor with lines lc rgb '#1030d0' lw 2.5 notitle";

    plot += marker_clauses(reference, vertex_motion, markers, factor, data);

    constexpr double relative_margin = 0.03; // white border around the mesh
    const double     margin =
      relative_margin * std::max(x_max - x_min, y_max - y_min);
    const std::string caption = fmt::format(
      "{}{}displacements x {:.3g}; colour: major principal compressive "
      "stress per cell, peak {:.3g} MPa in the blocks (base in sand, not "
      "coloured); drawn mirrored, face on the right",
      title,
      title.empty() ? "" : ", ",
      factor,
      peak);
    return fmt::format(
             "set title {}\n{}set size ratio -1\n"
             "set xlabel 'x from the face (m), drawn mirrored: face on the "
             "right, free end on the left'\nset ylabel 'y (m)'\n"
             "set xrange [{}:{}]\nset yrange [{}:{}]\n{}"
             "set cblabel 'major principal compressive stress (MPa, "
             "compression > 0; tension drawn as 0)'\n"
             "set cbrange [0:{}]\n"
             "set palette defined (0 '#d9e6f2', 0.25 '#fee391', 0.5 "
             "'#fe9929', 0.75 '#d94801', 1 '#67000d')\n",
             gnuplot_string(caption),
             markers.empty() ? "unset key\n" :
                               "set key outside center bottom horizontal\n",
             x_min - margin,
             x_max + margin,
             y_min - margin,
             y_max + margin,
             true_x_tics(x_min - margin, x_max + margin),
             peak > 0. ? peak : 1.) +
           data + plot + "\n";
  }

  double
  write_deformed_picture(
    const dealii::DoFHandler<2>                 &dof_handler,
    const dealii::TrilinosWrappers::MPI::Vector &displacement,
    const std::vector<double>                   &cell_stress,
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

    double largest = 0., x_min = 1e300, x_max = -1e300, y_min = 1e300,
           y_max = -1e300;
    for (unsigned int i = 0; i < vertices.size(); ++i)
      if (used[i])
        {
          largest = std::max(largest, motion[i].norm());
          x_min   = std::min(x_min, vertices[i][0]);
          x_max   = std::max(x_max, vertices[i][0]);
          y_min   = std::min(y_min, vertices[i][1]);
          y_max   = std::max(y_max, vertices[i][1]);
        }
    constexpr double drawn_fraction_of_width = 0.1;
    const double     factor =
      magnification > 0. ? magnification :
          largest > 0. ? drawn_fraction_of_width * (x_max - x_min) / largest :
                         1.;

    // Picture size follows the mesh extent so cells are not distorted;
    // extra room for the caption, the key and the colour box.
    constexpr unsigned int width_pixels = 1600, extra_height_pixels = 160;
    const unsigned int     height_pixels =
      static_cast<unsigned int>(width_pixels * (y_max - y_min) /
                                (x_max - x_min)) +
      extra_height_pixels;
    render_png(deformed_picture_script(
                 reference, motion, cell_stress, markers, factor, title),
               png_path,
               width_pixels,
               height_pixels);
    return factor;
  }
} // namespace FloorBlock::Output
