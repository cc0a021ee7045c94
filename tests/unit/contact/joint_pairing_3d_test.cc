// Issue 16: the joints of a 3D assembly (the 2D Gmsh mesh swept along the
// face, Geometry::extrude_assembly) pair node to node as in 2D.
#include <contact/joint_pairing.h>
#include <fem/fe_space.h>
#include <geometry/assembly_mesher.h>
#include <geometry/extruded_assembly.h>
#include <geometry/ids.h>
#include <geometry/triangulation_reader.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "rounded_mesh.h"

namespace
{
  using namespace FloorBlock;
  namespace Ids = Geometry::Ids;

  constexpr double face_length = 1.0; // m, two 0.5 m slices

  /** The default assembly (6 blocks, sharp corners) extruded. */
  const dealii::Triangulation<3> &
  extruded_default_assembly()
  {
    static const dealii::Triangulation<3> solid = [] {
      const auto folder =
        std::filesystem::temp_directory_path() /
        ("floorblock_pairing_3d_" + std::to_string(::getpid()));
      std::filesystem::create_directories(folder);
      const std::string             msh = (folder / "assembly.msh").string();
      Geometry::AssemblyDescription description;
      description.corner_rounding_radius = 0.;
      Geometry::write_gmsh_mesh(description, msh);
      dealii::Triangulation<2> flat;
      Geometry::read_triangulation(msh, flat);
      dealii::Triangulation<3> result;
      Geometry::extrude_assembly(flat,
                                 Geometry::uniform_slices(face_length, 0.5),
                                 result);
      std::filesystem::remove_all(folder);
      return result;
    }();
    return solid;
  }

  double
  side_area(const dealii::Triangulation<3>  &mesh,
            const dealii::types::boundary_id id)
  {
    double area = 0.;
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          area += face->measure();
    return area;
  }

  // Every node of both sides of every vertical joint has its coincident
  // partner; the weights add up to the joint's area, the normals are the
  // joint's (x) and the two sides' DoFs differ (distinct bodies).
  TEST(JointPairing3d, VerticalJointsPairNodeToNodeWithTheirArea)
  {
    const auto           &mesh = extruded_default_assembly();
    const Fem::FeSpace<3> space(mesh, 1);
    const unsigned int    n_blocks = Geometry::AssemblyDescription().n_blocks;
    for (unsigned int joint = 1; joint <= n_blocks; ++joint)
      {
        Contact::PairingSummary summary;
        const auto              pairs =
          Contact::pair_joint_nodes(space,
                                    Ids::vertical_joint_free_side(joint),
                                    Ids::vertical_joint_face_side(joint),
                                    joint,
                                    &summary);
        ASSERT_FALSE(pairs.empty());
        EXPECT_EQ(summary.n_coincident, pairs.size());
        EXPECT_EQ(summary.n_mirrored, 0u);
        double weight = 0.;
        for (const auto &pair : pairs)
          {
            weight += pair.weight;
            EXPECT_NEAR(std::abs(pair.normal[0]), 1., 1e-12)
              << "joint " << joint;
            EXPECT_NEAR(pair.normal[0], pairs.front().normal[0], 1e-12);
            for (unsigned int c = 0; c < 3; ++c)
              EXPECT_NE(pair.dofs_a[c], pair.dofs_b[c]);
          }
        const double area =
          side_area(mesh, Ids::vertical_joint_free_side(joint));
        EXPECT_NEAR(weight, area, 1e-12 * area) << "joint " << joint;
        // A vertical joint is a block height tall (the blocks follow the
        // bedding) and the face length long.
        EXPECT_NEAR(area,
                    Geometry::AssemblyDescription().block_height * face_length,
                    1e-9);
      }
  }

  // The bedding joints under every block and under the face block pair
  // the same way, with the bedding's curved normal (y = x^2/400 in x-y).
  TEST(JointPairing3d, BeddingJointsPairNodeToNode)
  {
    const auto           &mesh = extruded_default_assembly();
    const Fem::FeSpace<3> space(mesh, 1);
    const unsigned int    n_blocks = Geometry::AssemblyDescription().n_blocks;
    for (unsigned int block = 0; block <= n_blocks; ++block)
      {
        Contact::PairingSummary summary;
        const auto              pairs =
          Contact::pair_joint_nodes(space,
                                    Ids::bedding_block_side(block),
                                    Ids::bedding_base_side(block),
                                    block,
                                    &summary);
        ASSERT_FALSE(pairs.empty()) << "block " << block;
        EXPECT_EQ(summary.n_coincident, pairs.size());
        double weight = 0.;
        for (const auto &pair : pairs)
          {
            weight += pair.weight;
            EXPECT_NEAR(pair.normal.norm(), 1., 1e-12);
            EXPECT_NEAR(pair.normal[2], 0., 1e-12); // no slope along the face
          }
        const double area = side_area(mesh, Ids::bedding_block_side(block));
        EXPECT_NEAR(weight, area, 1e-12 * area) << "block " << block;
      }
  }

  // Rounded corners (the default scene's 1 cm fillets): the top fillets of
  // every vertical joint pair with their mirror images cross-section by
  // cross-section, so the 3D pairs are the 2D ones at every slice position
  // (three for two slices): as many coincident, mirrored and free nodes,
  // the same initial gaps, the joint's in-plane normal, and the mirrored
  // weights (fillet length projected on the joint line, times the length
  // of face a section stands for) adding up to the 2D ones times the face
  // length. Before, a 3D fillet node had no partner and the joint threw.
  TEST(JointPairing3d, RoundedFilletsPairWithTheirMirrorImagesInEverySection)
  {
    constexpr unsigned int              n_blocks    = 2;
    constexpr double                    rounding    = 0.01;  // m
    constexpr double                    corner_size = 0.005; // m
    constexpr unsigned int              n_sections  = 3;     // two 0.5 m slices
    const Geometry::AssemblyDescription description =
      Testing::level_assembly(n_blocks, rounding, corner_size);
    dealii::Triangulation<2> section;
    Testing::mesh_assembly(description, "fillet_pairing_3d", section);
    dealii::Triangulation<3> solid;
    Geometry::extrude_assembly(section,
                               Geometry::uniform_slices(face_length, 0.5),
                               solid);
    const Fem::FeSpace<2> plane_space(section, 1);
    const Fem::FeSpace<3> space(solid, 1);
    for (unsigned int joint = 1; joint <= n_blocks; ++joint)
      {
        Contact::PairingSummary plane_summary, summary;
        const auto              plane_pairs =
          Contact::pair_joint_nodes(plane_space,
                                    Ids::vertical_joint_face_side(joint),
                                    Ids::vertical_joint_free_side(joint),
                                    joint,
                                    &plane_summary);
        const auto pairs =
          Contact::pair_joint_nodes(space,
                                    Ids::vertical_joint_face_side(joint),
                                    Ids::vertical_joint_free_side(joint),
                                    joint,
                                    &summary);
        ASSERT_GT(plane_summary.n_mirrored, 0u) << "joint " << joint;
        EXPECT_EQ(summary.n_coincident,
                  n_sections * plane_summary.n_coincident);
        EXPECT_EQ(summary.n_mirrored, n_sections * plane_summary.n_mirrored);
        EXPECT_EQ(summary.n_free_a, n_sections * plane_summary.n_free_a);
        EXPECT_EQ(summary.n_free_b, n_sections * plane_summary.n_free_b);
        double plane_weight = 0., weight = 0., plane_gaps = 0., gaps = 0.;
        for (const auto &pair : plane_pairs)
          if (pair.initial_gap > 0.)
            {
              plane_weight += pair.weight;
              plane_gaps += pair.initial_gap;
            }
        for (const auto &pair : pairs)
          if (pair.initial_gap > 0.)
            {
              weight += pair.weight;
              gaps += pair.initial_gap;
              EXPECT_NEAR(pair.normal[0], plane_pairs.front().normal[0], 1e-12);
              EXPECT_NEAR(pair.normal[1], plane_pairs.front().normal[1], 1e-12);
              EXPECT_EQ(pair.normal[2], 0.);
            }
        ASSERT_GT(plane_gaps, 0.);
        EXPECT_NEAR(gaps, n_sections * plane_gaps, 1e-12 * gaps);
        EXPECT_NEAR(weight, face_length * plane_weight, 1e-12 * weight)
          << "joint " << joint;
      }
  }

  // A 3D side against a rigid plane: the gap is the distance along the
  // plane's normal, as in 2D.
  TEST(JointPairing3d, PlaneGapIsTheDistanceAlongTheNormal)
  {
    dealii::Triangulation<3> mesh;
    dealii::GridGenerator::subdivided_hyper_rectangle(
      mesh,
      {4, 2, 3},
      dealii::Point<3>(-1., 0., 0.),
      dealii::Point<3>(1., 0.5, 1.5),
      true); // bottom y = 0: id 2
    const Fem::FeSpace<3> space(mesh, 1);
    const auto            nodes =
      Contact::pair_nodes_with_plane(space,
                                     2,
                                     dealii::Point<3>(0.3, -0.1, 0.2),
                                     dealii::Tensor<1, 3>({0., -2., 0.}),
                                     0.,
                                     0);
    ASSERT_EQ(nodes.size(), 5u * 4u);
    double weight = 0.;
    for (const auto &node : nodes)
      {
        EXPECT_NEAR(node.initial_gap, 0.1, 1e-15);
        EXPECT_NEAR(node.normal[1], -1., 1e-15);
        weight += node.weight;
      }
    EXPECT_NEAR(weight, 2. * 1.5, 1e-12);
  }
} // namespace
