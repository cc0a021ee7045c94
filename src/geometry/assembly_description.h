#pragma once

#include <geometry/bedding_kinds.h>

namespace FloorBlock::Geometry
{
  /**
   * @brief Plain description of a block assembly: n blocks of width L and
   * height H, the fixed face block next to block n, and a base (bedding
   * layer) below all of them. All lengths in m, angles in rad.
   *
   * Defaults are the UDEC scene of chapter section 6.5/6.6.2: six blocks
   * 1 m wide and 2 m high on the parabola y = x^2/400. The parameter parser
   * fills this struct; geometry never reads a ParameterHandler.
   */
  struct AssemblyDescription
  {
    /** Number of sliding blocks n (1..99). */
    unsigned int n_blocks = 6;
    /** Block width L perpendicular to the face. Units: m. */
    double block_width = 1.0;
    /** Block height H, measured vertically. Units: m. */
    double block_height = 2.0;
    /** Width of the fixed face block; the parser sets it to L when absent.
     * Units: m. */
    double face_block_width = 1.0;
    /** Vertical thickness of the base (bedding layer) below the joint. Units:
     * m. */
    double base_thickness = 0.5;
    /**
     * No base body: the blocks stand on a rigid half-plane below the
     * bedding, which the contact solver models as an obstacle.
     */
    bool rigid_base = false;

    BeddingShape bedding_shape = BeddingShape::parabolic;
    /** Inclination alpha of a planar bedding, rising away from the face. Units:
     * rad. */
    double inclination = 0.0;
    /** Curvature parameter k of the parabolic bedding y = x^2/k. Units: m. */
    double      curvature    = 400.0;
    FloorUplift floor_uplift = FloorUplift::inclined_bedding;

    /**
     * Corner rounding (Geometry/Corner rounding radius): each fillet starts
     * this far from the corner along the vertical side, as UDEC's corner
     * rounding length does, so both sides of a vertical joint keep the same
     * straight part. It is the arc radius at a right-angled corner; at an
     * interior angle theta the arc radius is r tan(theta/2). 0 = sharp.
     * Units: m.
     */
    double corner_rounding_radius = 0.0;

    /** Target cell size at the contact corners. Units: m. */
    double mesh_corner_size = 0.05;
    /** Largest cell size, away from the corners. Units: m. */
    double mesh_far_size = 0.25;
    /** Ratio of neighbouring cell sizes away from a corner (> 1). Units: 1. */
    double mesh_growth_rate = 1.3;
    /** Same nodes on both sides of every joint (node-to-node contact). */
    bool matching_joints = true;
  };

  /**
   * @brief Refuse geometry that cannot be built, before Gmsh is called.
   *
   * Checks sizes (positive, finite), the number of blocks (1..99, and no
   * more than fit on a parabola before its slope exceeds the limit below),
   * the bedding inclination, the mesh sizes and growth rate, and that the
   * corner fillets fit on every side of every block.
   *
   * @throws FloorBlock::InputError naming the parameter ("Geometry/..." or
   * "Mesh/..."), its value and the allowed range.
   */
  void
  validate(const AssemblyDescription &description);

  /**
   * Steepest bedding inclination accepted anywhere under the blocks. With
   * vertical block sides, an inclination alpha makes the block a
   * parallelogram with an interior angle of 90 deg - alpha; beyond 60 deg
   * the 30 deg corner cannot be meshed with sound quadrilaterals. Units: rad.
   */
  constexpr double max_bedding_inclination = 1.0471975511965976; // 60 deg

  /**
   * Smallest accepted ratio mesh_corner_size / min(L, H): guards against
   * meshes of millions of cells by a typo. Units: 1.
   */
  constexpr double min_relative_corner_size = 1.0e-3;

  /**
   * Smallest accepted ratio of a local size request (LocalSize) to
   * min(L, H). A quarter of the corner bound: the full-quad recombination
   * leaves cells about twice the request, and the floor safety factor's
   * paths need cells of a few tenths of a millimetre where the critical
   * distance is about 1 cm (Scene::critical_distance_sizes()); local
   * requests cover small zones, not the whole block. Units: 1.
   */
  constexpr double min_relative_local_size = min_relative_corner_size / 4.;
} // namespace FloorBlock::Geometry
