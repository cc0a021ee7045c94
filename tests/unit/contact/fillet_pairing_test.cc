// Node pairing across rounded block corners: mirror-meshed top fillets of a
// vertical joint pair with an initial gap, bottom fillets stay free.
#include <contact/joint_pairing.h>
#include <fem/fe_space.h>
#include <geometry/ids.h>

#include <deal.II/dofs/dof_tools.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "rounded_mesh.h"

namespace
{
  using namespace FloorBlock;
  namespace Ids = Geometry::Ids;

  constexpr double rounding    = 0.01;  // m, UDEC rounding length r
  constexpr double corner_size = 0.005; // m, r / 2
  /** Mirror distances are compared to this (m): round-off of Gmsh arc nodes. */
  constexpr double geometric_tolerance = 1e-12;

  /** Distinct vertices of the faces carrying boundary id @p side. */
  std::vector<dealii::Point<2>>
  side_vertices(const dealii::Triangulation<2>  &mesh,
                const dealii::types::boundary_id side)
  {
    std::set<unsigned int>        seen;
    std::vector<dealii::Point<2>> vertices;
    for (const auto &face : mesh.active_face_iterators())
      if (face->at_boundary() && face->boundary_id() == side)
        for (const unsigned int v : face->vertex_indices())
          if (seen.insert(face->vertex_index(v)).second)
            vertices.push_back(face->vertex(v));
    return vertices;
  }

  TEST(FilletPairing, TopFilletNodesPairWithTheirMirrorImageAcrossTheJoint)
  {
    constexpr unsigned int              n_blocks = 2;
    const Geometry::AssemblyDescription description =
      Testing::level_assembly(n_blocks, rounding, corner_size);
    dealii::Triangulation<2> mesh;
    Testing::mesh_assembly(description, "fillet_pairing", mesh);
    const Fem::FeSpace<2>         space(mesh, 1);
    std::vector<dealii::Point<2>> support_points(space.dof_handler().n_dofs());
    dealii::DoFTools::map_dofs_to_support_points(space.mapping(),
                                                 space.dof_handler(),
                                                 support_points);
    // Level floor at y = H: both fillets start at y_s = H - r on the joint
    // line and are quarter circles of radius r.
    const double fillet_start = description.block_height - rounding;
    for (unsigned int joint = 1; joint <= n_blocks; ++joint)
      {
        const double joint_x = (n_blocks - joint) * description.block_width;
        Contact::PairingSummary summary;
        const auto              pairs =
          Contact::pair_joint_nodes(space,
                                    Ids::vertical_joint_face_side(joint),
                                    Ids::vertical_joint_free_side(joint),
                                    joint,
                                    &summary);
        // Every node of both sides has a partner.
        EXPECT_EQ(
          pairs.size(),
          side_vertices(mesh, Ids::vertical_joint_face_side(joint)).size());
        EXPECT_EQ(
          pairs.size(),
          side_vertices(mesh, Ids::vertical_joint_free_side(joint)).size());
        EXPECT_EQ(summary.n_free_a, 0u);
        EXPECT_EQ(summary.n_free_b, 0u);
        unsigned int n_fillet_nodes = 0;
        for (const auto &node :
             side_vertices(mesh, Ids::vertical_joint_face_side(joint)))
          if (node[1] > fillet_start + geometric_tolerance)
            ++n_fillet_nodes;
        // At least 4 cells over each fillet (the mesher's minimum).
        EXPECT_GE(n_fillet_nodes, 4u);
        EXPECT_EQ(summary.n_mirrored, n_fillet_nodes);

        for (const auto &pair : pairs)
          {
            const dealii::Point<2> &a = pair.position;
            const dealii::Point<2> &b = support_points[pair.dofs_b[0]];
            if (a[1] <= fillet_start + geometric_tolerance)
              {
                EXPECT_EQ(pair.initial_gap, 0.) << a;
                continue;
              }
            // Side A (block j+1 / face block) lies at x < x_j on the circle
            // centred at (x_j - r, y_s); its partner is its mirror image.
            const dealii::Point<2> centre(joint_x - rounding, fillet_start);
            EXPECT_NEAR(a.distance(centre), rounding, geometric_tolerance) << a;
            EXPECT_NEAR(b[0], 2. * joint_x - a[0], geometric_tolerance) << a;
            EXPECT_NEAR(b[1], a[1], geometric_tolerance) << a;
            EXPECT_NEAR(pair.initial_gap,
                        2. * (joint_x - a[0]),
                        geometric_tolerance)
              << a;
            EXPECT_GT(pair.initial_gap, 0.) << a;
            // The joint normal, not the tilted fillet normal.
            EXPECT_NEAR(pair.normal[0], 1., geometric_tolerance);
            EXPECT_NEAR(pair.normal[1], 0., geometric_tolerance);
            EXPECT_GE(pair.weight, 0.);
          }
      }

    // Bedding: the base side is straight under the bottom fillets, so those
    // nodes have no partner; they are left free, the common part pairs.
    for (unsigned int block = 1; block <= n_blocks; ++block)
      {
        Contact::PairingSummary summary;
        const auto              pairs =
          Contact::pair_joint_nodes(space,
                                    Ids::bedding_base_side(block),
                                    Ids::bedding_block_side(block),
                                    n_blocks + block,
                                    &summary);
        EXPECT_EQ(summary.n_mirrored, 0u);
        EXPECT_GT(summary.n_free_b, 0u);
        EXPECT_EQ(pairs.size(), summary.n_coincident);
        for (const auto &pair : pairs)
          EXPECT_EQ(pair.initial_gap, 0.);
      }
  }

  TEST(FilletPairing, ProjectedFilletWeightsAddUpToTheRoundingLength)
  {
    // Weight of a fillet pair = integral of N (n_face . n) ds, so the
    // fillet nodes above the first one sum to the height they cover: the
    // last fillet face's node at y_s keeps its own full face integral.
    // Checked here: all weights of a vertical joint add up to the joint
    // height minus the bottom rounding length, up to the y_s node's share
    // of its fillet face (arc vs its height: second order in the cell angle).
    const Geometry::AssemblyDescription description =
      Testing::level_assembly(1, rounding, corner_size);
    dealii::Triangulation<2> mesh;
    Testing::mesh_assembly(description, "fillet_weights", mesh);
    const Fem::FeSpace<2> space(mesh, 1);
    const auto            pairs =
      Contact::pair_joint_nodes(space,
                                Ids::vertical_joint_face_side(1),
                                Ids::vertical_joint_free_side(1),
                                1);
    double total = 0.;
    for (const auto &pair : pairs)
      total += pair.weight;
    // Straight part H - 2r plus the fillet's height r.
    const double expected = description.block_height - rounding;
    // First fillet face: chord c = 2 r sin(phi/2) with phi the angle per
    // cell (at most pi/8); its half counted as length instead of height
    // differs by c/2 (1 - cos(phi/2)) < r phi^3 / 16.
    const double phi = M_PI / 8.;
    EXPECT_NEAR(total, expected, rounding * std::pow(phi, 3) / 16.);
  }

  TEST(FilletPairing, SlopedFloorLeavesNonMirrorFilletsFree)
  {
    // Blocks on y = x^2/100: the floor is sloped at the joints, so the
    // interior angles of the two top corners differ (90 deg +- slope) and so
    // do the fillet radii: no node has a mirror partner. The pairing must
    // not fail; the fillet nodes stay free (documented limit).
    Geometry::AssemblyDescription description;
    description.n_blocks               = 2;
    description.curvature              = 100.;
    description.corner_rounding_radius = rounding;
    description.mesh_corner_size       = corner_size;
    dealii::Triangulation<2> mesh;
    Testing::mesh_assembly(description, "sloped_fillets", mesh);
    const Fem::FeSpace<2>   space(mesh, 1);
    Contact::PairingSummary summary;
    const auto              pairs =
      Contact::pair_joint_nodes(space,
                                Ids::vertical_joint_face_side(1),
                                Ids::vertical_joint_free_side(1),
                                1,
                                &summary);
    EXPECT_EQ(summary.n_mirrored, 0u);
    EXPECT_GT(summary.n_free_a, 0u);
    EXPECT_EQ(summary.n_free_a, summary.n_free_b);
    EXPECT_EQ(pairs.size(), summary.n_coincident);
  }
} // namespace
