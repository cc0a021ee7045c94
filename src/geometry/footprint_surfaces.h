#pragma once

#include <deal.II/grid/tria.h>

#include <vector>

namespace FloorBlock::Geometry
{
  /**
   * @brief Gives the top faces of @p loaded_blocks that lie within the
   * support footprint z in [@p footprint_start, @p footprint_end] the id
   * Ids::footprint_surface(i) instead of Ids::floor_surface(i), so that
   * the support pressure acts on them alone.
   *
   * Pre-condition: both footprint ends are slice positions of the swept
   * mesh (footprint_slices()), so a face is inside when its centre is:
   * no face straddles an end.
   *
   * @param[in] loaded_blocks Chapter block numbers (1 = free end).
   * @param[in] footprint_start, footprint_end z range (m), start < end.
   * @param[in,out] solid The swept assembly (extrude_assembly()).
   * @return The number of faces tagged.
   */
  unsigned int
  tag_footprint(const std::vector<unsigned int> &loaded_blocks,
                const double                     footprint_start,
                const double                     footprint_end,
                dealii::Triangulation<3>        &solid);
} // namespace FloorBlock::Geometry
