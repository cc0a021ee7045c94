#pragma once

#include <geometry/assembly_description.h>

#include <deal.II/base/types.h>

#include <vector>

namespace FloorBlock::Geometry
{
  /** A point of the x-y plane. Units: m. */
  struct Point2
  {
    double x;
    double y;
  };

  /** Kind of a boundary segment of a body outline. */
  enum class SegmentKind
  {
    line,
    quadratic, ///< quadratic Bezier: an exact piece of the parabolic bedding
    arc        ///< circular arc shorter than half a circle: a corner fillet
  };

  /**
   * @brief One piece of a body boundary: the kernel-independent description
   * that the 2D Gmsh builder turns into a curve (and that a 3D builder would
   * extrude by the support width b).
   */
  struct Segment
  {
    SegmentKind kind;
    Point2      start;
    Point2      end;
    /** Middle Bezier control point (quadratic) or centre (arc); unused for
     * lines. */
    Point2                     control;
    dealii::types::boundary_id boundary_id;
  };

  /** @brief Closed, counter-clockwise boundary of one body. */
  struct BodyOutline
  {
    dealii::types::material_id material_id;
    std::vector<Segment>       segments;
  };

  /** Position of a segment: index of the body, index of the segment in it. */
  struct SegmentRef
  {
    unsigned int body;
    unsigned int segment;
  };

  /**
   * @brief Two segments of different bodies with identical geometry: the two
   * sides of a joint (or of the part of it between corner fillets). The
   * master belongs to the body farther from the face (vertical joints) or to
   * the block (bedding joint).
   */
  struct JointPair
  {
    SegmentRef master;
    SegmentRef slave;
  };

  /**
   * @brief The two top fillets that face each other across vertical joint
   * j: master = block j's top-left fillet (id 2000+j), slave = the top-right
   * fillet of block j+1 or of the face block (id 3000+j).
   */
  struct FilletPair
  {
    SegmentRef master;
    SegmentRef slave;
    /** x of the joint line (m). */
    double joint_x;
    /**
     * Whether the slave is the mirror image of the master about x =
     * joint_x (to round-off): true where the floor is level at the joint
     * (flat bedding, e.g. the lifted reading), false on a sloped floor,
     * where the interior angles of the two corners differ and so do the
     * arc radii r tan(theta/2).
     */
    bool mirror;
  };

  /** @brief All bodies of a scene and how their joint sides pair up. */
  struct AssemblyOutline
  {
    /** Blocks 1..n (in this order), then the face block, then the base. */
    std::vector<BodyOutline> bodies;
    std::vector<JointPair>   joint_pairs;
    /** Top fillets across every vertical joint (empty without rounding). */
    std::vector<FilletPair> fillet_pairs;
    /** Contact corners where the mesh is refined (floor-level joint corners,
     * block corners on the bedding). */
    std::vector<Point2> refinement_points;
  };

  /**
   * @brief Build the outline of every body of the scene (pure geometry, no
   * Gmsh). Block i occupies x in [(n-i)L, (n-i+1)L]; its base lies on the
   * bedding profile, its sides are vertical and its top is the bedding
   * shifted up by H; the base is the bedding shifted down by the base
   * thickness. See src/geometry/README.md for the sketch.
   *
   * @throws FloorBlock::InputError if the corner fillets do not fit.
   * Pre-condition: the simple range checks of validate() passed.
   */
  AssemblyOutline
  build_outline(const AssemblyDescription &description);

  /**
   * @brief Exact area enclosed by a body outline (Green's theorem, exact for
   * lines, quadratic Bezier pieces and arcs). Units: m^2.
   */
  double
  outline_area(const BodyOutline &body);

  /** @brief Length of a fillet arc (radius times swept angle). Units: m. */
  double
  arc_length(const Segment &arc);

  /**
   * @brief Whether @p second is the mirror image of @p first about the
   * vertical line x = @p mirror_x, in either direction, with every
   * coordinate within @p tolerance (m).
   */
  bool
  mirror_geometry(const Segment &first,
                  const Segment &second,
                  const double   mirror_x,
                  const double   tolerance);

  /**
   * @brief Whether two segments describe the same curve bit for bit, in
   * either direction.
   */
  bool
  same_geometry(const Segment &first, const Segment &second);
} // namespace FloorBlock::Geometry
