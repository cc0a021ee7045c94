#pragma once

#include <deal.II/grid/tria.h>

#include <vector>

namespace FloorBlock::Geometry
{
  /**
   * @brief Slice positions z_0 = 0 < z_1 < ... < z_m = @p face_length for
   * extrude_assembly(): m = ceil(face_length / slice_size) equal slices.
   * Pre-conditions: both arguments are positive (the parameters' ranges).
   */
  std::vector<double>
  uniform_slices(double face_length, double slice_size);

  /**
   * @brief Slice positions through both ends of a footprint
   * [@p footprint_start, @p footprint_end] on the face: the three parts
   * [0, start], [start, end], [end, face_length] each in
   * uniform_slices() of at most @p slice_size (a part of zero length
   * gets none). So the footprint's ends are slice positions, and every
   * face swept from a 2D edge lies wholly inside or outside it.
   * Pre-conditions: 0 <= start < end <= face_length, slice_size > 0.
   */
  std::vector<double>
  footprint_slices(double face_length,
                   double slice_size,
                   double footprint_start,
                   double footprint_end);

  /**
   * @brief The 3D block assembly: the 2D assembly mesh (a Gmsh mesh read
   * by read_triangulation(), not refined) swept along z through
   * @p slice_coordinates, each quadrilateral becoming one hexahedron per
   * slice.
   *
   * Why an extrusion of the 2D mesh and not a 3D Gmsh mesh: the joint
   * sides of the 2D mesh already carry the same nodes (Gmsh periodic
   * constraints, assembly_mesher.h), and every body is swept through the
   * same slices, so the two faces of every 3D joint carry the same nodes
   * by construction -- coincident but distinct vertices, one set per body,
   * as in 2D. Refinement toward the corners comes with the 2D mesh;
   * toward a footprint it is the choice of the slices.
   *
   * Material ids are those of the 2D cells. A 2D boundary id becomes the
   * id of the side faces swept from it (the joint sides, floor surfaces
   * and outer sides keep their ids.h meaning); the end faces get
   * Ids::end_face_near (z = 0) and Ids::end_face_far (z = face length).
   *
   * @throws dealii exceptions if @p assembly is refined (deal.II extrudes
   *   coarse meshes only) or @p slice_coordinates are not increasing.
   */
  void
  extrude_assembly(const dealii::Triangulation<2> &assembly,
                   const std::vector<double>      &slice_coordinates,
                   dealii::Triangulation<3>       &result);
} // namespace FloorBlock::Geometry
