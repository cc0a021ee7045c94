#pragma once

#include <deal.II/base/types.h>

#include <string>

namespace FloorBlock::Geometry::Ids
{
  /**
   * @file
   * @brief The one place where material and boundary ids of a block assembly
   * are defined. The Gmsh builder uses them as physical-group tags and the FE
   * code reads them back from the deal.II triangulation.
   *
   * Numbering follows the chapter: block 1 is at the free end, block n next
   * to the fixed face block. Vertical joint j (1 <= j <= n) lies between
   * block j and block j+1; joint n lies between block n and the face block.
   * x is measured from the face (x = 0 on joint n), positive away from it;
   * y points up.
   *
   * Corner fillets (Geometry/Corner rounding radius > 0) carry the id of the
   * side they round into, chosen by where contact happens:
   *  - a top fillet (floor level) belongs to the vertical side below it
   *    (joint side 2000+j / 3000+j, or the outer side 7004 / 7005), because
   *    the top corner of a vertical joint is where the lateral force Q acts;
   *  - a bottom fillet belongs to the block bottom 4000+i, because a
   *    rotating block presses its bottom corner into the bedding.
   * So with rounding a vertical joint side is its straight part plus the
   * top fillet, and the two sides coincide only on the straight part; the
   * top fillets face each other across the joint (mirror images on a level
   * floor) and are paired with an initial gap by Contact::pair_joint_nodes.
   */

  /** Largest number of blocks the id scheme can number (material ids 1..99). */
  constexpr unsigned int max_n_blocks = 99;

  /** @name Material ids */
  ///@{
  /** Material id of block i (1 <= i <= max_n_blocks). */
  constexpr dealii::types::material_id
  block_material(const unsigned int block)
  {
    return block;
  }
  constexpr dealii::types::material_id face_block_material = 100;
  constexpr dealii::types::material_id base_material       = 101;
  ///@}

  /** Manifold id of the chart that keeps the bedding exact under refinement
   * (bedding_manifold.h). */
  constexpr dealii::types::manifold_id bedding_manifold = 1;

  /** @name Boundary ids (equal to the Gmsh physical tags of the curves) */
  ///@{
  /**
   * Vertical joint j, the side that belongs to block j (the body farther
   * from the face).
   */
  constexpr dealii::types::boundary_id
  vertical_joint_free_side(const unsigned int joint)
  {
    return 2000 + joint;
  }

  /**
   * Vertical joint j, the side that belongs to block j+1, or to the face
   * block when j = n.
   */
  constexpr dealii::types::boundary_id
  vertical_joint_face_side(const unsigned int joint)
  {
    return 3000 + joint;
  }

  /** Bedding joint under block i: the block bottom (i = 0: face block). */
  constexpr dealii::types::boundary_id
  bedding_block_side(const unsigned int block)
  {
    return 4000 + block;
  }

  /** Bedding joint under block i: the base top (i = 0: under the face block).
   */
  constexpr dealii::types::boundary_id
  bedding_base_side(const unsigned int block)
  {
    return 5000 + block;
  }

  /** Floor surface (block top, where supports press); i = 0: face block. */
  constexpr dealii::types::boundary_id
  floor_surface(const unsigned int block)
  {
    return 6000 + block;
  }

  /** Index used for the face block in the per-body functions above. */
  constexpr unsigned int face_block_index = 0;

  constexpr dealii::types::boundary_id base_bottom           = 7001;
  constexpr dealii::types::boundary_id base_end_face_side    = 7002;
  constexpr dealii::types::boundary_id base_end_free_side    = 7003;
  constexpr dealii::types::boundary_id free_side_of_block_1  = 7004;
  constexpr dealii::types::boundary_id face_block_outer_side = 7005;
  /**
   * 3D scenes (extruded_assembly.h): the two end faces of every body,
   * at z = 0 and at z = Geometry/Face length (the face runs along z).
   */
  constexpr dealii::types::boundary_id end_face_near = 7006;
  constexpr dealii::types::boundary_id end_face_far  = 7007;

  /**
   * 3D scenes with a support footprint (Loading/Footprint length > 0,
   * src/geometry/footprint_surfaces.h): the top of loaded block i where
   * it lies under the support, z within the footprint. The rest of that
   * top keeps floor_surface(i). Its own id, not a pressure switched on by
   * position, because the FE assembly looks loads up by boundary id (as
   * in 2D), and because the footprint's ends are slice positions of the
   * swept mesh, so that every top face lies wholly inside or outside and
   * the loaded area is the footprint exactly.
   */
  constexpr dealii::types::boundary_id
  footprint_surface(const unsigned int block)
  {
    return 8000 + block;
  }
  ///@}

  /** What a boundary id denotes, decoded from its value. */
  enum class BoundaryKind
  {
    vertical_joint_free_side,
    vertical_joint_face_side,
    bedding_block_side,
    bedding_base_side,
    floor_surface,
    footprint_surface,
    outer,
    unknown
  };

  /** Boundary ids are <kind base> + <index>, with kind bases 1000 apart. */
  constexpr unsigned int boundary_kind_spacing = 1000;

  /** @brief Classify a boundary id of the scheme above (header-only, so output code needs no link to this library). */
  constexpr BoundaryKind
  boundary_kind(const dealii::types::boundary_id id)
  {
    const unsigned int kind  = id / boundary_kind_spacing;
    const unsigned int index = id % boundary_kind_spacing;
    if (kind == 2 && index >= 1)
      return BoundaryKind::vertical_joint_free_side;
    if (kind == 3 && index >= 1)
      return BoundaryKind::vertical_joint_face_side;
    if (kind == 4)
      return BoundaryKind::bedding_block_side;
    if (kind == 5)
      return BoundaryKind::bedding_base_side;
    if (kind == 6)
      return BoundaryKind::floor_surface;
    if (kind == 8 && index >= 1)
      return BoundaryKind::footprint_surface;
    if (id >= base_bottom && id <= end_face_far)
      return BoundaryKind::outer;
    return BoundaryKind::unknown;
  }

  /**
   * @brief Index carried by a boundary id: the joint j or block i it names
   * (0 for the face block, 0 for outer boundaries).
   */
  constexpr unsigned int
  boundary_index(const dealii::types::boundary_id id)
  {
    return boundary_kind(id) == BoundaryKind::outer ?
             0 :
             id % boundary_kind_spacing;
  }

  /** @brief Whether a boundary id is one side of a vertical or bedding joint. */
  constexpr bool
  is_joint_side(const dealii::types::boundary_id id)
  {
    const BoundaryKind kind = boundary_kind(id);
    return kind == BoundaryKind::vertical_joint_free_side ||
           kind == BoundaryKind::vertical_joint_face_side ||
           kind == BoundaryKind::bedding_block_side ||
           kind == BoundaryKind::bedding_base_side;
  }

  /** @brief Human-readable name of a boundary id, e.g. "joint 3, block 4 side". */
  std::string
  boundary_name(const dealii::types::boundary_id id,
                const unsigned int               n_blocks);

  /** @brief Human-readable name of a material id, e.g. "block 2". */
  std::string
  material_name(const dealii::types::material_id id);

  /**
   * @brief The whole id scheme for an assembly of n blocks as a text table
   * (for `floorblock mesh --ids`).
   * @param[in] n_blocks Number of blocks, 1 <= n_blocks <= max_n_blocks.
   */
  std::string
  id_table(const unsigned int n_blocks);
} // namespace FloorBlock::Geometry::Ids
