#include <common/input_error.h>
#include <corner/corner_site.h>
#include <scene/assembly_inputs.h>

#include <cmath>

namespace FloorBlock::Corner
{
  CornerSite
  floor_corner_site(const Parameters::ScenarioParameters &scene,
                    const unsigned int                    joint)
  {
    const unsigned int n = scene.geometry.n_blocks;
    if (joint < 1 || joint > n)
      throw InputError("corner: joint " + std::to_string(joint) +
                       " does not exist; allowed: 1 to " + std::to_string(n) +
                       " (Geometry/Number of blocks)");
    const Geometry::AssemblyOutline outline =
      Geometry::build_outline(Scene::assembly_description(scene));
    CornerSite site;
    site.joint           = joint;
    site.joint_name      = "vertical " + std::to_string(joint);
    site.rounding_radius = scene.geometry.corner_rounding_radius;

    // Block `joint` (body joint - 1) owns the joint's master side; the
    // upper end of its vertical segment is where the straight joint ends.
    bool found = false;
    for (const Geometry::JointPair &pair : outline.joint_pairs)
      if (pair.master.body == joint - 1)
        {
          const Geometry::Segment &side =
            outline.bodies[pair.master.body].segments[pair.master.segment];
          if (std::abs(side.end.x - side.start.x) > 1e-9)
            continue; // the block's bedding side
          const Geometry::Point2 upper =
            side.start.y > side.end.y ? side.start : side.end;
          if (!found || upper.y > site.corner.y)
            site.corner = upper;
          found = true;
        }
    if (!found)
      throw std::logic_error("floor_corner_site: no vertical side of joint " +
                             std::to_string(joint) + " in the outline");
    site.top = site.corner.y + site.rounding_radius;
    return site;
  }
} // namespace FloorBlock::Corner
