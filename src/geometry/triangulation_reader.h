#pragma once

#include <deal.II/grid/tria.h>

#include <string>

namespace FloorBlock::Geometry
{
  /**
   * @brief Read a block-assembly mesh written by write_gmsh_mesh() into a
   * deal.II triangulation, with the physical surface tags as material ids
   * and the physical curve tags as boundary ids (ids.h).
   *
   * The nodes on the two sides of a joint stay distinct vertices, so every
   * joint side is a tagged boundary and the bodies are not connected.
   * Cells have straight edges: a curved bedding is represented by its
   * chords unless a manifold is attached afterwards.
   *
   * @param[in] msh_path Gmsh 4.1 ASCII .msh file.
   * @param[out] triangulation Cleared first, then filled.
   * @throws std::runtime_error if the file cannot be read.
   */
  void
  read_triangulation(const std::string        &msh_path,
                     dealii::Triangulation<2> &triangulation);
} // namespace FloorBlock::Geometry
