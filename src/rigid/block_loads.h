#pragma once

#include <rigid/model_description.h>

#include <deal.II/base/point.h>

#include <array>
#include <vector>

namespace FloorBlock::RigidBlocks
{
  /** @brief Loads of one block at full load factor (per metre of face). */
  struct BlockLoads
  {
    /** Self weight W = rho g L H (N/m), acting down at the centroid. */
    double weight = 0.;
    /** Support line load P (N/m), acting down at support_point. */
    double support_load = 0.;
    /** Point of the block top where P acts (m). */
    dealii::Point<2> support_point;
    /** Centroid (m): the reference point of the block's motion. */
    dealii::Point<2> centroid;
  };

  /** @brief Loads of every block, index i - 1 (chapter numbering). */
  std::vector<BlockLoads>
  block_loads(const ModelDescription &description);

  /**
   * @brief Generalised applied force (F_x, F_y in N/m, moment about the
   * centroid in N m/m, counter-clockwise positive) at the given factors of
   * gravity and support load.
   */
  std::array<double, 3>
  applied_force(const BlockLoads &loads,
                const double      gravity_factor,
                const double      support_factor);
} // namespace FloorBlock::RigidBlocks
