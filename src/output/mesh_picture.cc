#include <geometry/ids.h>
#include <output/gnuplot.h>
#include <output/mesh_picture.h>

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace FloorBlock::Output
{
  namespace
  {
    namespace Ids = Geometry::Ids;

    /** Fill colour of a body: neighbouring blocks alternate, face block grey,
     * base sand. */
    std::string
    body_colour(const dealii::types::material_id material)
    {
      if (material == Ids::face_block_material)
        return "#a0a0a0";
      if (material == Ids::base_material)
        return "#e3cf9a";
      constexpr std::array<const char *, 3> block_colours{
        {"#8fb8de", "#a8d5a2", "#f2b880"}};
      return block_colours[material % block_colours.size()];
    }

    /** Cell outlines as closed polygons, one gnuplot data block per body. */
    std::map<dealii::types::material_id, std::string>
    cell_polygons(const dealii::Triangulation<2> &triangulation)
    {
      // deal.II vertex order is lexicographic; this visits them around the
      // cell.
      constexpr std::array<unsigned int, 5> around{{0, 1, 3, 2, 0}};
      std::map<dealii::types::material_id, std::ostringstream> streams;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          std::ostringstream &stream = streams[cell->material_id()];
          for (const unsigned int vertex : around)
            stream << cell->vertex(vertex)[0] << ' ' << cell->vertex(vertex)[1]
                   << '\n';
          stream << '\n';
        }
      std::map<dealii::types::material_id, std::string> polygons;
      for (const auto &[material, stream] : streams)
        polygons[material] = stream.str();
      return polygons;
    }

    /** Boundary faces for which @p wanted is true, as separate line segments. */
    template <typename Predicate>
    std::string
    boundary_segments(const dealii::Triangulation<2> &triangulation,
                      const Predicate                &wanted)
    {
      std::ostringstream stream;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && wanted(face->boundary_id()))
            stream << face->vertex(0)[0] << ' ' << face->vertex(0)[1] << '\n'
                   << face->vertex(1)[0] << ' ' << face->vertex(1)[1] << "\n\n";
      // gnuplot refuses an empty data file: a lone point far off-screen is not
      // drawn.
      const std::string text = stream.str();
      return text.empty() ? std::string("NaN NaN\n") : text;
    }

  } // namespace

  /** Marker colour by category: joint states first, others after. */
  std::string
  marker_colour(const std::string &category, const unsigned int index)
  {
    static const std::map<std::string, std::string> known = {
      {"stick", "#1a9850"}, {"slip", "#f46d43"}, {"open", "#7b3294"}};
    constexpr std::array<const char *, 3> others{
      {"#000000", "#2166ac", "#b2182b"}};
    const auto found = known.find(category);
    return found != known.end() ? found->second : others[index % others.size()];
  }

  std::string
  gnuplot_string(const std::string &text)
  {
    std::string result = "'";
    for (const char character : text)
      result +=
        character == '\'' ? std::string("''") : std::string(1, character);
    return result + "'";
  }

  void
  write_mesh_picture(const dealii::Triangulation<2> &triangulation,
                     const std::string              &png_path,
                     const MeshPictureOptions       &options)
  {
    if (triangulation.n_active_cells() == 0)
      throw std::runtime_error("cannot draw an empty mesh");
    const auto         polygons = cell_polygons(triangulation);
    std::ostringstream plot;
    unsigned int       block_index = 0;
    std::string        cells_text;
    for (const auto &[material, text] : polygons)
      {
        cells_text += text + "\n\n";
        plot << (block_index == 0 ? "plot " : ", \\\n     ") << "$cells index "
             << block_index << " with filledcurves closed fc rgb '"
             << body_colour(material)
             << "' fs solid 1.0 noborder notitle, \\\n     $cells index "
             << block_index << " with lines lc rgb '#505050' lw 0.4 notitle";
        ++block_index;
      }
    // Inline data blocks: no scratch files to clean up.
    std::string data =
      "$cells << EOD\n" + cells_text + "EOD\n$joints << EOD\n" +
      boundary_segments(triangulation, Ids::is_joint_side) +
      "EOD\n$floor << EOD\n" +
      boundary_segments(triangulation,
                        [](const dealii::types::boundary_id id) {
                          return Ids::boundary_kind(id) ==
                                 Ids::BoundaryKind::floor_surface;
                        }) +
      "EOD\n";
    plot << ", \\\n     $joints with lines lc rgb '#d01010' lw 2.5 notitle"
         << ", \\\n     $floor with lines lc rgb '#1030d0' lw 2.5 notitle";
    std::map<std::string, std::ostringstream> marker_points;
    for (const PictureMarker &marker : options.markers)
      marker_points[marker.category] << marker.position[0] << ' '
                                     << marker.position[1] << '\n';
    unsigned int marker_index = 0;
    for (const auto &[category, points] : marker_points)
      {
        const std::string name = "$markers" + std::to_string(marker_index);
        data += name + " << EOD\n" + points.str() + "EOD\n";
        plot << ", \\\n     " << name << " with points pt 7 ps 0.6 lc rgb '"
             << marker_colour(category, marker_index) << "' title "
             << gnuplot_string(category);
        ++marker_index;
      }
    plot << '\n';

    // Picture size follows the mesh extent so cells are not distorted.
    constexpr double huge  = std::numeric_limits<double>::max();
    double           x_min = huge, x_max = -huge, y_min = huge, y_max = -huge;
    for (const auto &vertex : triangulation.get_vertices())
      {
        x_min = std::min(x_min, vertex[0]);
        x_max = std::max(x_max, vertex[0]);
        y_min = std::min(y_min, vertex[1]);
        y_max = std::max(y_max, vertex[1]);
      }
    constexpr double relative_margin = 0.03; // white border around the mesh
    const double     margin =
      relative_margin * std::max(x_max - x_min, y_max - y_min);
    constexpr unsigned int title_pixels = 60; // room for the caption
    const unsigned int     height =
      options.height_pixels > 0 ?
            options.height_pixels :
            static_cast<unsigned int>(options.width_pixels *
                                  (y_max - y_min + 2 * margin) /
                                  (x_max - x_min + 2 * margin)) +
          (options.title.empty() ? 0 : title_pixels);

    std::ostringstream script;
    script.precision(17);
    script << "set title " << gnuplot_string(options.title) << '\n'
           << (options.markers.empty() ? "unset key\n" :
                                         "set key outside right top\n")
           << "set size ratio -1\nset xlabel 'x (m)'\n"
           << "set ylabel 'y (m)'\n"
           << "set xrange [" << x_min - margin << ':' << x_max + margin
           << "]\nset yrange [" << y_min - margin << ':' << y_max + margin
           << "]\n"
           << data << plot.str();
    render_png(script.str(), png_path, options.width_pixels, height);
  }
} // namespace FloorBlock::Output
