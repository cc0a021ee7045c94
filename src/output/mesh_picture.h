#pragma once

#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /** @brief A labelled point drawn over the mesh (e.g. a joint node's state). */
  struct PictureMarker
  {
    dealii::Point<2> position;
    /** Legend entry; markers of one category share a colour. */
    std::string category;
  };

  /** @brief Size, caption and overlays of a mesh picture. */
  struct MeshPictureOptions
  {
    /** Image width. Units: pixels. */
    unsigned int width_pixels = 1600;
    /** Image height; 0 = from the aspect ratio of the mesh. Units: pixels. */
    unsigned int height_pixels = 0;
    /** Caption printed above the mesh (may be empty). */
    std::string title;
    /** Points drawn on top, coloured by category, with a legend. */
    std::vector<PictureMarker> markers;
  };

  /** @brief Marker colour by category: joint states first, others after. */
  std::string
  marker_colour(const std::string &category, const unsigned int index);

  /** @brief @p text as a single-quoted gnuplot string. */
  std::string
  gnuplot_string(const std::string &text);

  /**
   * @brief Draw a block-assembly mesh as a PNG with gnuplot: cells filled
   * with one colour per body (material id), cell edges thin, joint sides
   * (ids.h: vertical and bedding joints) thick red, the floor surface blue.
   *
   * gnuplot (Debian package gnuplot-nox, pngcairo terminal) must be on the
   * PATH. The PNG appears atomically (temporary name, then rename).
   *
   * @param[in] triangulation Mesh read by Geometry::read_triangulation().
   * @param[in] png_path Output file.
   * @param[in] options Image size and caption.
   * @throws std::runtime_error if gnuplot fails or is missing.
   */
  void
  write_mesh_picture(const dealii::Triangulation<2> &triangulation,
                     const std::string              &png_path,
                     const MeshPictureOptions       &options = {});
} // namespace FloorBlock::Output
