#pragma once

#include <geometry/assembly_description.h>

#include <deal.II/grid/tria.h>

#include <string>

namespace FloorBlock::Testing
{
  /**
   * @brief A flat (level) block assembly with rounded corners: n blocks of
   * 1 m x 2 m, face block, base, planar bedding at 0 rad.
   * @param[in] n_blocks Number of blocks.
   * @param[in] rounding Corner rounding length r (m), 0 = sharp.
   * @param[in] corner_size Cell size at the contact corners (m).
   */
  Geometry::AssemblyDescription
  level_assembly(const unsigned int n_blocks,
                 const double       rounding,
                 const double       corner_size);

  /**
   * @brief Meshes @p description with Gmsh into a scratch file named after
   * @p name and reads it into @p triangulation (bedding manifold attached).
   */
  void
  mesh_assembly(const Geometry::AssemblyDescription &description,
                const std::string                   &name,
                dealii::Triangulation<2>            &triangulation);
} // namespace FloorBlock::Testing
