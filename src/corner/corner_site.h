#pragma once

#include <geometry/body_outline.h>
#include <parameters/scenario_parameters.h>

#include <string>

namespace FloorBlock::Corner
{
  /**
   * @brief The floor-level (top) corner of a vertical joint in the
   * reference geometry: where the two blocks' top corners meet and the
   * corner stress concentrates.
   */
  struct CornerSite
  {
    unsigned int joint = 0;  ///< chapter numbering: n is the face joint
    std::string  joint_name; ///< as in the joint tables: "vertical <joint>"
    /** Corner fillet radius (m); 0 for sharp corners. */
    double rounding_radius = 0.;
    /**
     * Where the joint's straight part ends at the top (m): the sharp
     * corner itself, or where the fillets leave the joint line.
     */
    Geometry::Point2 corner;
    /** Top of the blocks at the joint (m): corner.y + rounding radius. */
    double top = 0.;
  };

  /**
   * @brief The top corner of vertical joint @p joint of @p scene (1..n).
   * @throws FloorBlock::InputError for a joint outside 1..n.
   */
  CornerSite
  floor_corner_site(const Parameters::ScenarioParameters &scene,
                    unsigned int                          joint);
} // namespace FloorBlock::Corner
