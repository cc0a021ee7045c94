#pragma once

#include <geometry/assembly_description.h>

#include <deal.II/grid/tria.h>

namespace FloorBlock::Geometry
{
  /**
   * First manifold id of the corner fillets (one per fillet arc, in outline
   * order); Ids::bedding_manifold is the chart of all other boundary curves.
   */
  constexpr dealii::types::manifold_id first_fillet_manifold = 2;

  /**
   * @brief Lets deal.II refinement of a scene mesh put new boundary vertices
   * on the scene's curves, as a finer Gmsh mesh would:
   *  - faces on a corner fillet (both vertices on the arc's circle, the
   *    face centre inside its sweep) get a SphericalManifold about the arc
   *    centre, one id per arc (first_fillet_manifold + k);
   *  - every other boundary face gets the BeddingManifold chart, which is
   *    exact for all of them: bedding-following curves (y - y_b(x)
   *    constant) and vertical sides (x constant);
   *  - cells and interior faces stay flat, so an interior hanging vertex
   *    lies on its coarse neighbour's straight face.
   * Call again after every refinement: refined faces inherit their ids,
   * but the manifold objects are removed by detach_boundary_manifolds().
   */
  void
  attach_boundary_manifolds(const AssemblyDescription &description,
                            dealii::Triangulation<2>  &triangulation);

  /**
   * @brief Removes every manifold and makes all ids flat, so that the
   * finite-element mapping sees straight-sided cells through the vertices,
   * like on a Gmsh mesh: a refined mesh then differs from the coarse one
   * only in its vertices, not in how cells between them are mapped.
   */
  void
  detach_boundary_manifolds(dealii::Triangulation<2> &triangulation);

  /**
   * @brief Halves every cell @p n_refinements times, new boundary vertices
   * on the scene's curves (attach_boundary_manifolds(), then detached):
   * the nested meshes of Mesh/Global refinements and of `converge --mode
   * uniform`. Joint sides stay matched: coincident faces (and mirror-image
   * fillet faces) split at coincident (mirror-image) points.
   */
  void
  refine_globally_on_curves(const AssemblyDescription &description,
                            const unsigned int         n_refinements,
                            dealii::Triangulation<2>  &triangulation);
} // namespace FloorBlock::Geometry
