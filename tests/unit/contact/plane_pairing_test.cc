// Node pairing with a rigid obstacle: the plane's initial gap, and the
// parabolic obstacle of JointDefinition::obstacle_curvature (the Hertz case
// of `verify hertz`).
#include <contact/joint_pairing.h>
#include <fem/fe_space.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

namespace
{
  using namespace FloorBlock;

  /** colorize: the bottom face y = 0 of the rectangle gets boundary id 2. */
  constexpr dealii::types::boundary_id bottom = 2;

  void
  make_block(dealii::Triangulation<2> &mesh)
  {
    dealii::GridGenerator::subdivided_hyper_rectangle(
      mesh, {8, 2}, dealii::Point<2>(-1., 0.), dealii::Point<2>(1., 0.5), true);
  }

  TEST(PlanePairing, GapIsTheDistanceToThePlaneAlongItsNormal)
  {
    dealii::Triangulation<2> mesh;
    make_block(mesh);
    const Fem::FeSpace<2> space(mesh, 1);
    // Plane 0.1 m below the face, normal from the body into the obstacle.
    const auto nodes =
      Contact::pair_nodes_with_plane(space,
                                     bottom,
                                     dealii::Point<2>(0.3, -0.1),
                                     dealii::Tensor<1, 2>({0., -2.}),
                                     0.,
                                     0);
    ASSERT_EQ(nodes.size(), 9u);
    for (const auto &node : nodes)
      {
        EXPECT_NEAR(node.initial_gap, 0.1, 1e-15);
        EXPECT_NEAR(node.normal[1], -1., 1e-15);
      }
  }

  // Curvature 1/R: the obstacle x^2 / (2R) below the face touching at the
  // plane point, so the gap grows with the distance along the plane.
  TEST(PlanePairing, ParabolicObstacleAddsHalfTheCurvatureTimesDistanceSquared)
  {
    dealii::Triangulation<2> mesh;
    make_block(mesh);
    const Fem::FeSpace<2> space(mesh, 1);
    const double          radius = 4.;
    const auto            nodes =
      Contact::pair_nodes_with_plane(space,
                                     bottom,
                                     dealii::Point<2>(0.25, 0.),
                                     dealii::Tensor<1, 2>({0., -1.}),
                                     1. / radius,
                                     0);
    ASSERT_EQ(nodes.size(), 9u);
    for (const auto &node : nodes)
      {
        const double s = node.position[0] - 0.25;
        EXPECT_NEAR(node.initial_gap, s * s / (2. * radius), 1e-15);
      }
  }
} // namespace
