#pragma once

#include <geometry/body_outline.h>

#include <vector>

namespace FloorBlock::Geometry
{
  /** @brief Gmsh tags of the entities built for an assembly outline. */
  struct GmshAssembly
  {
    /** OCC surface tag of every body, in outline order. */
    std::vector<int> surface_tags;
    /** OCC curve tag of every segment: curve_tags[body][segment]. */
    std::vector<std::vector<int>> curve_tags;
  };

  /**
   * @brief Create the 2D OCC geometry of an assembly in the current Gmsh
   * model: one plane surface per body, each with its own points and curves
   * (nothing is fragmented or fused, so the two sides of a joint stay
   * distinct entities), then synchronize and add the physical groups
   * (surface tag = material id, curve tag = boundary id, from ids.h).
   *
   * Every curve is created in a canonical direction (from the
   * lexicographically smaller end), so the two sides of a joint are the
   * same parametrised curve and mesh identically.
   *
   * Pre-condition: a GmshScope is open and a model is current.
   * A 3D scene would extrude these surfaces by the support width b
   * (gmsh::model::occ::extrude) and map curve groups to surface groups.
   */
  GmshAssembly
  build_gmsh_geometry(const AssemblyOutline &outline);
} // namespace FloorBlock::Geometry
