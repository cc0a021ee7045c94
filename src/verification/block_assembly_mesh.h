#pragma once

#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace FloorBlock::Verification
{
  /** A structured rectangular body of a verification mesh (m). */
  struct BlockSpec
  {
    double                     x_min, x_max, y_min, y_max;
    unsigned int               n_x, n_y;
    dealii::types::material_id material;
    dealii::types::boundary_id left, right, bottom, top;
    /** Faces of the right side above split_y get right_upper instead. */
    double                     split_y     = 1e300;
    dealii::types::boundary_id right_upper = 0;
    /** Faces of the top right of split_x get top_right instead. */
    double                     split_x   = 1e300;
    dealii::types::boundary_id top_right = 0;
  };

  /**
   * @brief Builds several bodies into one triangulation without merging
   * their coincident vertices (each body has its own vertices), so joints
   * carry duplicated nodes as in the Gmsh block assembly. Used by the
   * verification cases (patch, incline, two blocks) and the unit tests.
   */
  void
  make_block_assembly(const std::vector<BlockSpec> &blocks,
                      dealii::Triangulation<2>     &triangulation);
} // namespace FloorBlock::Verification
