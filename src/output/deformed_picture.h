#pragma once

#include <output/mesh_picture.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /**
   * @brief Draws the block assembly displaced by @p magnification times the
   * displacement field (one PNG, through write_mesh_picture), with @p markers
   * (e.g. joint node states) moved by the same field.
   *
   * @param[in] dof_handler Vector-valued (dim components) displacement space.
   * @param[in] displacement Solution vector on @p dof_handler (m).
   * @param[in] markers Reference positions and categories; each is moved
   *   with the displacement of its vertex (the nearest vertex of the mesh).
   * @param[in] magnification Factor on the displacement; 0 = automatic: the
   *   largest displacement drawn as 10 % of the assembly width.
   * @return The magnification used.
   */
  double
  write_deformed_picture(
    const dealii::DoFHandler<2>                 &dof_handler,
    const dealii::TrilinosWrappers::MPI::Vector &displacement,
    const std::vector<PictureMarker>            &markers,
    const std::string                           &png_path,
    const double                                 magnification = 0.,
    const std::string                           &title         = "");
} // namespace FloorBlock::Output
