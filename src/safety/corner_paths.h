#pragma once

#include <geometry/body_outline.h>
#include <parameters/scenario_parameters.h>

#include <string>
#include <vector>

namespace FloorBlock::Safety
{
  /**
   * @brief The path from one floor-level block corner into its block, along
   * which the critical-distance methods read the stress.
   *
   * The hot spot is the corner where a vertical joint meets the block
   * tops: the contact stress of Eqs. 6.51-6.53 peaks there. The path runs
   * along the inward bisector of the block's right-angled corner, from the
   * corner's surface point: the sharp corner itself, or the middle of its
   * fillet of radius r, (sqrt(2) - 1) r along the bisector from the sharp
   * corner. The bisector is the direction symmetric to both faces the
   * corner joins, the joint (loaded in compression) and the free top; for
   * r much smaller than L it leaves the path, hence the stress at L/2,
   * nearly independent of r.
   */
  struct CornerPath
  {
    unsigned int     joint = 0;  ///< chapter numbering: n is the face joint
    std::string      joint_name; ///< "vertical <joint>"
    std::string      block;      ///< "block j", "block j+1" or "face block"
    Geometry::Point2 start;      ///< the corner's surface point (m)
    Geometry::Point2 direction;  ///< unit, into the block

    /** "face block at vertical 6": how reports and estimates name it. */
    std::string
    label() const
    {
      return block + " at " + joint_name;
    }
  };

  /**
   * @brief Both top corners of every vertical joint of a 2D scene: block
   * j's (the joint's +x side) and block j+1's or the face block's.
   */
  std::vector<CornerPath>
  floor_corner_paths(const Parameters::ScenarioParameters &scene);
} // namespace FloorBlock::Safety
