// deal.II refinement of a scene mesh must put new boundary vertices on the
// scene's curves (fillet arcs, parabolic bedding), like a finer Gmsh mesh,
// and leave a flat, manifold-free mesh for the solver afterwards.
#include <geometry/bedding_profile.h>
#include <geometry/body_outline.h>
#include <geometry/ids.h>
#include <geometry/refinement_manifolds.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_meshes.h"

namespace FloorBlock::Geometry
{
  namespace
  {
    struct Circle
    {
      dealii::Point<2> centre;
      double           radius;
    };

    std::vector<Circle>
    fillet_circles(const AssemblyDescription &description)
    {
      std::vector<Circle> circles;
      for (const auto &body : build_outline(description).bodies)
        for (const auto &segment : body.segments)
          if (segment.kind == SegmentKind::arc)
            {
              const dealii::Point<2> centre(segment.control.x,
                                            segment.control.y);
              circles.push_back(
                {centre,
                 centre.distance(
                   dealii::Point<2>(segment.start.x, segment.start.y))});
            }
      return circles;
    }

    /** Largest distance of a fillet-face vertex from its circle (m), and the
     * count of such faces. */
    std::pair<double, unsigned int>
    fillet_deviation(const dealii::Triangulation<2> &mesh,
                     const std::vector<Circle>      &circles)
    {
      double       largest = 0.;
      unsigned int n_faces = 0;
      for (const auto &cell : mesh.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              face->manifold_id() >= first_fillet_manifold &&
              face->manifold_id() != dealii::numbers::flat_manifold_id)
            {
              const Circle &circle =
                circles.at(face->manifold_id() - first_fillet_manifold);
              ++n_faces;
              for (const unsigned int v : {0u, 1u})
                largest =
                  std::max(largest,
                           std::abs(face->vertex(v).distance(circle.centre) -
                                    circle.radius));
            }
      return {largest, n_faces};
    }

    double
    bedding_deviation(const dealii::Triangulation<2> &mesh,
                      const BeddingProfile           &profile)
    {
      double largest = 0.;
      for (const auto &cell : mesh.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && Ids::boundary_kind(face->boundary_id()) ==
                                       Ids::BoundaryKind::bedding_base_side)
            for (const unsigned int v : {0u, 1u})
              largest = std::max(largest,
                                 std::abs(face->vertex(v)[1] -
                                          profile.height(face->vertex(v)[0])));
      return largest;
    }
  } // namespace

  TEST(RefinementManifolds, NewVerticesLieOnFilletsAndBedding)
  {
    const auto &scene   = Testing::meshed_scene("rounded");
    const auto  circles = fillet_circles(scene.description);
    const auto  profile = BeddingProfile::geometry_profile(scene.description);

    dealii::Triangulation<2> refined, chords;
    refined.copy_triangulation(scene.triangulation);
    attach_boundary_manifolds(scene.description, refined);
    const auto [coarse_deviation, n_coarse_faces] =
      fillet_deviation(refined, circles);
    // 5 blocks with 4 fillets each, every fillet at least 4 faces.
    EXPECT_GE(n_coarse_faces, 4u * 4u * 5u);
    EXPECT_LT(coarse_deviation, 1e-9);

    refined.refine_global(1);
    const auto [deviation, n_faces] = fillet_deviation(refined, circles);
    EXPECT_EQ(n_faces, 2 * n_coarse_faces);
    EXPECT_LT(deviation, 1e-12);
    EXPECT_LT(bedding_deviation(refined, profile), 1e-12);

    detach_boundary_manifolds(refined);
    for (const auto &cell : refined.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        EXPECT_EQ(face->manifold_id(), dealii::numbers::flat_manifold_id);

    // Without the manifolds the midpoints sit on chords: the checks above
    // can fail (sagitta of a 0.05 m fillet's 4-cell chords, about 5e-4 m).
    chords.copy_triangulation(scene.triangulation);
    attach_boundary_manifolds(scene.description, chords);
    chords.reset_all_manifolds();
    chords.refine_global(1);
    EXPECT_GT(fillet_deviation(chords, circles).first, 1e-5);
    EXPECT_GT(bedding_deviation(chords, profile), 1e-7);
  }
} // namespace FloorBlock::Geometry
