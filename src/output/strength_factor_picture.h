#pragma once

#include <safety/strength_factor_field.h>

#include <string>

namespace FloorBlock::Output
{
  /**
   * @brief gnuplot script of strength_factor.png: the Hoek-Brown strength
   * factor around a floor-level corner (Safety::strength_factor_map()),
   * coloured from 0 to 2, the contour FS = 1 drawn in black, the corner's
   * path over the critical distance @p critical_distance (m) in white;
   * points outside the blocks left blank.
   */
  std::string
  strength_factor_plot(const Safety::StrengthFactorMap &map,
                       double                           critical_distance);
} // namespace FloorBlock::Output
