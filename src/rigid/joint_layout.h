#pragma once

#include <rigid/model_description.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace FloorBlock::RigidBlocks
{
  /** Which body one side of a joint belongs to. */
  enum class BodyKind
  {
    block,      ///< a free rigid block (3 DOF)
    face_block, ///< fixed
    base        ///< moved rigidly by the prescribed uplift field
  };

  /** @brief A body: its kind and, for a block, its index i - 1. */
  struct BodyRef
  {
    BodyKind     kind  = BodyKind::block;
    unsigned int index = 0;
  };

  enum class JointKind
  {
    vertical, ///< between block j and block j+1 (or the face block, j = n)
    bedding   ///< between block i and the base
  };

  /** @brief One integration point of a joint, in the undeformed scene. */
  struct JointPoint
  {
    /** Position (m). */
    dealii::Point<2> position;
    /** Trapezoid weight: length of joint this point stands for (m). */
    double weight = 0.;
    /**
     * Distance along the joint from its start (m): depth below floor level
     * for a vertical joint, horizontal distance from the face-side end for
     * a bedding joint.
     */
    double coordinate = 0.;
    /** Unit normal pointing from side A into side B. */
    dealii::Tensor<1, 2> normal;
    /**
     * Unit tangent: up (+y) on a vertical joint, along the bedding away from
     * the face on a bedding joint.
     */
    dealii::Tensor<1, 2> tangent;
  };

  /**
   * @brief One joint. Side A is block j of vertical joint j (the body
   * farther from the face) or the base of a bedding joint; side B is block
   * j+1 / the face block, or the block on the bedding.
   */
  struct JointGeometry
  {
    JointKind kind = JointKind::vertical;
    /** Chapter number: j of vertical joint j, i of the bedding under block i.
     */
    unsigned int number = 0;
    /** "vertical 6", "bedding 3". */
    std::string             name;
    BodyRef                 side_a;
    BodyRef                 side_b;
    std::vector<JointPoint> points;
  };

  /**
   * @brief Reference point of block i (index i - 1): its centroid (m). The
   * block spans x in [(n-i)L, (n-i+1)L] between the bedding y_b(x) and
   * y_b(x) + H, so the centroid is at the middle of that x range and
   * \f$ y_c = \frac{1}{L}\int y_b\,dx + H/2 \f$.
   */
  dealii::Point<2>
  block_centroid(const Geometry::AssemblyDescription &assembly,
                 const unsigned int                   block_index);

  /**
   * @brief All joints of the scene with their integration points: vertical
   * joints 1..n, then bedding joints under blocks 1..n. Trapezoid rule with
   * @p n_points points per joint, both end points included, so the floor
   * level corner of a vertical joint is sampled exactly. A bedding point
   * weight includes the arc length factor \f$\sqrt{1 + y_b'^2}\f$.
   */
  std::vector<JointGeometry>
  build_joints(const Geometry::AssemblyDescription &assembly,
               const unsigned int                   n_points);
} // namespace FloorBlock::RigidBlocks
