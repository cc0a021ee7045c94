#pragma once

#include <output/mesh_picture.h>

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /**
   * @brief gnuplot script (after the terminal) of the deformed block
   * assembly: every cell a polygon filled by its stress on a colour scale,
   * joint sides and floor drawn over it, @p markers on top.
   *
   * The picture is mirrored in x (x_picture = -x) so that the face is on
   * the right and the free end on the left, as in the README's block
   * numbering diagram; the tick labels give the true x, and the axis label
   * and the title say that it is mirrored.
   *
   * Data blocks `$cells` (the blocks and the face block, coloured) and
   * `$base` (the base, drawn in one colour: its stress comes from the
   * prescribed bending): per active cell, in active_cell_index() order, its
   * closed outline (5 rows "x_picture_m y_m stress_MPa"), cells separated
   * by a blank line.
   *
   * @param[in] reference Undeformed mesh.
   * @param[in] vertex_motion Displacement of every vertex (m), by vertex
   *   index.
   * @param[in] cell_stress Major principal compressive stress per active
   *   cell, compression positive (Pa).
   * @param[in] markers Reference positions and categories; each is moved
   *   with the displacement of its nearest vertex.
   * @param[in] factor Magnification of the displacement (-).
   * @param[in] title Caption's first part (may be empty).
   */
  std::string
  deformed_picture_script(
    const dealii::Triangulation<2>          &reference,
    const std::vector<dealii::Tensor<1, 2>> &vertex_motion,
    const std::vector<double>               &cell_stress,
    const std::vector<PictureMarker>        &markers,
    const double                             factor,
    const std::string                       &title);

  /**
   * @brief Draws the block assembly displaced by @p magnification times the
   * displacement field and coloured by @p cell_stress (one PNG, see
   * deformed_picture_script()).
   *
   * @param[in] dof_handler Vector-valued (2 components) displacement space.
   * @param[in] displacement Solution vector on @p dof_handler (m).
   * @param[in] cell_stress Major principal compressive stress per active
   *   cell, compression positive (Pa).
   * @param[in] markers Reference positions and categories (e.g. joint node
   *   states).
   * @param[in] magnification Factor on the displacement; 0 = automatic: the
   *   largest displacement drawn as 10 % of the assembly width.
   * @return The magnification used.
   */
  double
  write_deformed_picture(
    const dealii::DoFHandler<2>                 &dof_handler,
    const dealii::TrilinosWrappers::MPI::Vector &displacement,
    const std::vector<double>                   &cell_stress,
    const std::vector<PictureMarker>            &markers,
    const std::string                           &png_path,
    const double                                 magnification = 0.,
    const std::string                           &title         = "");
} // namespace FloorBlock::Output
