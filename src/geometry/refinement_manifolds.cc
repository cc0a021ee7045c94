#include <geometry/bedding_manifold.h>
#include <geometry/body_outline.h>
#include <geometry/ids.h>
#include <geometry/refinement_manifolds.h>

#include <deal.II/grid/manifold_lib.h>

#include <cmath>
#include <vector>

namespace FloorBlock::Geometry
{
  namespace
  {
    struct Arc
    {
      dealii::Point<2> centre;
      dealii::Point<2> start;
      dealii::Point<2> end;
      double           radius;
    };

    dealii::Point<2>
    point(const Point2 &p)
    {
      return {p.x, p.y};
    }

    std::vector<Arc>
    fillet_arcs(const AssemblyDescription &description)
    {
      std::vector<Arc> arcs;
      for (const auto &body : build_outline(description).bodies)
        for (const auto &segment : body.segments)
          if (segment.kind == SegmentKind::arc)
            arcs.push_back(
              {point(segment.control),
               point(segment.start),
               point(segment.end),
               point(segment.start).distance(point(segment.control))});
      return arcs;
    }

    double
    cross(const dealii::Tensor<1, 2> &a, const dealii::Tensor<1, 2> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    /**
     * Both vertices on the circle and the centre between the arc's ends
     * (an arc is shorter than half a circle, so "between" is the sign of
     * two cross products).
     */
    bool
    lies_on(const Arc &arc, const dealii::TriaAccessor<1, 2, 2> &face)
    {
      // Gmsh places arc nodes and SphericalManifold new vertices to
      // round-off of the radius; 1e-9 relative is far above that and far
      // below any cell of a fillet.
      const double tolerance = 1e-9 * arc.radius + 1e-14;
      for (const unsigned int v : {0u, 1u})
        if (std::abs(face.vertex(v).distance(arc.centre) - arc.radius) >
            tolerance)
          return false;
      const auto   to_start = arc.start - arc.centre;
      const auto   to_end   = arc.end - arc.centre;
      const auto   to_face  = face.center() - arc.centre;
      const double sweep    = cross(to_start, to_end);
      return cross(to_start, to_face) * sweep > 0. &&
             cross(to_face, to_end) * sweep > 0.;
    }
  } // namespace

  void
  attach_boundary_manifolds(const AssemblyDescription &description,
                            dealii::Triangulation<2>  &triangulation)
  {
    const std::vector<Arc> arcs = fillet_arcs(description);
    triangulation.set_all_manifold_ids(dealii::numbers::flat_manifold_id);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            dealii::types::manifold_id id = Ids::bedding_manifold;
            for (std::size_t k = 0; k < arcs.size(); ++k)
              if (lies_on(arcs[k], *face))
                id = first_fillet_manifold + k;
            face->set_manifold_id(id);
          }
    triangulation.set_manifold(Ids::bedding_manifold,
                               BeddingManifold(BeddingProfile::geometry_profile(
                                 description)));
    for (std::size_t k = 0; k < arcs.size(); ++k)
      triangulation.set_manifold(first_fillet_manifold + k,
                                 dealii::SphericalManifold<2>(arcs[k].centre));
  }

  void
  detach_boundary_manifolds(dealii::Triangulation<2> &triangulation)
  {
    triangulation.reset_all_manifolds();
    triangulation.set_all_manifold_ids(dealii::numbers::flat_manifold_id);
  }

  void
  refine_globally_on_curves(const AssemblyDescription &description,
                            const unsigned int         n_refinements,
                            dealii::Triangulation<2>  &triangulation)
  {
    attach_boundary_manifolds(description, triangulation);
    triangulation.refine_global(n_refinements);
    detach_boundary_manifolds(triangulation);
  }
} // namespace FloorBlock::Geometry
