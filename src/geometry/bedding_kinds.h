#pragma once

/**
 * The bedding choices of a block assembly, with no other dependency, so that
 * the parameters library parses Bedding/Shape and Bedding/Floor uplift
 * reading straight into them (CMake target floorblock_geometry_kinds).
 */
namespace FloorBlock::Geometry
{
  /** Shape of the bedding joint on which the blocks stand. */
  enum class BeddingShape
  {
    planar,   ///< y = x tan(alpha)
    parabolic ///< y = x^2 / k for x >= 0 (chapter section 6.6.2)
  };

  /**
   * Which of the chapter's two readings of "floor uplift" the scene uses.
   * See src/geometry/README.md for the sketch.
   */
  enum class FloorUplift
  {
    /**
     * The bedding is already inclined (planar or parabolic) and the blocks
     * stand on it (Figure 6.1, 6.3; the analytic equations 6.1-6.46 use the
     * bedding inclination alpha_i under each block). The mesh follows the
     * profile.
     */
    inclined_bedding,
    /**
     * The bedding starts flat and is lifted with the planar or parabolic
     * profile, as the UDEC model "moved the bedding upwards" (section 6.5).
     * The mesh is flat; the profile is a displacement the solver prescribes
     * (see BeddingProfile::uplift_profile()).
     */
    lifted_flat_bedding
  };
} // namespace FloorBlock::Geometry
