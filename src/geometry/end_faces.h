#pragma once

/**
 * The boundary condition on the two end faces of a 3D scene (ids
 * Ids::end_face_near, Ids::end_face_far), with no other dependency, so
 * that the parameters library parses Geometry/End faces straight into it
 * (CMake target floorblock_geometry_kinds).
 */
namespace FloorBlock::Geometry
{
  /** What holds the ends of the assembly swept along the face. */
  enum class EndFaces
  {
    /**
     * u_z = 0 on both end faces (x and y free): the ends of a face much
     * longer than the model, whose neighbours along the face deform
     * alike. With loads and supports uniform along z the 3D answer is the
     * 2D plane-strain one.
     */
    plane_strain,
    /** Traction-free end faces: the assembly ends there. */
    free
  };
} // namespace FloorBlock::Geometry
