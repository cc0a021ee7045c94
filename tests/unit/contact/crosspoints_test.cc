// Unit tests of crosspoint_pairs (contact/crosspoints.h) on hand-built 2D
// pairs: which pairs yield (leave the exact law) at a block corner on a
// rigid or an elastic bedding, compliant joints, and pairs against a rigid
// obstacle that share a node with an exact two-sided joint.
#include <contact/crosspoints.h>

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace
{
  using namespace FloorBlock::Contact;
  using dealii::types::global_dof_index;

  /** Mesh node i has the DoFs 2i, 2i + 1. */
  std::array<global_dof_index, 2>
  dofs_of(const unsigned int mesh_node)
  {
    return {{2 * mesh_node, 2 * mesh_node + 1}};
  }

  ContactNode<2>
  pair(const unsigned int          joint,
       const dealii::Point<2>     &position,
       const double                weight,
       const dealii::Tensor<1, 2> &normal,
       const unsigned int          node_a,
       const unsigned int          node_b)
  {
    ContactNode<2> node;
    node.joint    = joint;
    node.position = position;
    node.weight   = weight;
    node.normal   = normal;
    node.dofs_a   = dofs_of(node_a);
    node.dofs_b   = dofs_of(node_b);
    return node;
  }

  ContactNode<2>
  obstacle_pair(const unsigned int          joint,
                const dealii::Point<2>     &position,
                const double                weight,
                const dealii::Tensor<1, 2> &normal,
                const unsigned int          node_a)
  {
    ContactNode<2> node = pair(joint, position, weight, normal, node_a, 0);
    node.dofs_b         = {
              {dealii::numbers::invalid_dof_index, dealii::numbers::invalid_dof_index}};
    return node;
  }

  const dealii::Tensor<1, 2> horizontal({1., 0.});
  const dealii::Tensor<1, 2> vertical({0., 1.});

  /** Mesh nodes of two unit blocks L (x < 0), R (x > 0) and a base. */
  enum MeshNode : unsigned int
  {
    corner_l = 0, // block L, (0, 0)
    corner_r,     // block R, (0, 0)
    base_corner,  // base, (0, 0)
    middle_l,     // (0, 0.5)
    middle_r,
    top_l, // (0, 1)
    top_r,
    base_left, // (-0.5, 0)
    bottom_l,
    base_right, // (0.5, 0)
    bottom_r
  };

  /**
   * Joint 0: the vertical joint L -> R (normal (1, 0)) at y = 0, 0.5, 1
   * with weights 0.25, 0.5, 0.25; then the bedding of L (joint 1) at
   * x = -0.5, 0 and of R (joint 2) at x = 0, 0.5, weights 0.25 each,
   * base -> block (normal (0, 1)). The three coincident nodes at (0, 0)
   * form the pairs 0 (L-R), 4 (base-L) and 5 (base-R).
   */
  std::vector<ContactNode<2>>
  block_corner_on_elastic_base()
  {
    return {pair(0, {0., 0.}, 0.25, horizontal, corner_l, corner_r),
            pair(0, {0., 0.5}, 0.5, horizontal, middle_l, middle_r),
            pair(0, {0., 1.}, 0.25, horizontal, top_l, top_r),
            pair(1, {-0.5, 0.}, 0.25, vertical, base_left, bottom_l),
            pair(1, {0., 0.}, 0.25, vertical, base_corner, corner_l),
            pair(2, {0., 0.}, 0.25, vertical, base_corner, corner_r),
            pair(2, {0.5, 0.}, 0.25, vertical, base_right, bottom_r)};
  }

  /** The same two blocks on a rigid bedding: joints 1, 2 on the plane. */
  std::vector<ContactNode<2>>
  block_corner_on_rigid_base()
  {
    return {pair(0, {0., 0.}, 0.25, horizontal, corner_l, corner_r),
            pair(0, {0., 0.5}, 0.5, horizontal, middle_l, middle_r),
            pair(0, {0., 1.}, 0.25, horizontal, top_l, top_r),
            obstacle_pair(1, {-0.5, 0.}, 0.25, vertical, bottom_l),
            obstacle_pair(1, {0., 0.}, 0.25, vertical, corner_l),
            obstacle_pair(2, {0., 0.}, 0.25, vertical, corner_r),
            obstacle_pair(2, {0.5, 0.}, 0.25, vertical, bottom_r)};
  }

  /** The marks as a vector of the pair indices marked. */
  std::vector<unsigned int>
  marked(const std::vector<bool> &yields)
  {
    std::vector<unsigned int> indices;
    for (unsigned int p = 0; p < yields.size(); ++p)
      if (yields[p])
        indices.push_back(p);
    return indices;
  }

  using Indices = std::vector<unsigned int>;

  /** No Dirichlet DoF among the 2 x 11 DoFs of the mesh nodes above. */
  dealii::IndexSet
  no_fixed_dofs()
  {
    return dealii::IndexSet(22);
  }

  /**
   * Pins down the rigid-base corner: of the three pairs on the corner
   * nodes only the vertical joint's (joint 0, listed before the bedding)
   * yields; the bedding pairs against the plane that share its nodes
   * stay exact, and so do the other pairs of the vertical joint. One
   * mark per pair.
   */
  TEST(Crosspoints, BlockCornerOnRigidBaseMarksVerticalPair)
  {
    const std::vector<ContactNode<2>> nodes = block_corner_on_rigid_base();
    const std::vector<bool>           yields =
      crosspoint_pairs(nodes, {true, true, true}, no_fixed_dofs());
    ASSERT_EQ(yields.size(), nodes.size());
    EXPECT_EQ(marked(yields), Indices({0}));
  }

  /**
   * Pins down the elastic-base corner of the doc (three coincident nodes:
   * block corners a, b and the base node; pairs a-b of joint 0, base-a
   * of joint 1, base-b of joint 2): only the redundant vertical pair
   * yields, "the bedding keeps exact contact at the block corners". The
   * six constraints at the corner have rank four, so one pair (two
   * constraints) is enough. The base node is shared by the two bedding
   * joints, which alone close no cycle: an earlier rule that keyed mesh
   * nodes marked the base-a pair too ({0, 4}).
   */
  TEST(Crosspoints, BlockCornerOnElasticBaseKeepsBothBeddingPairs)
  {
    const std::vector<ContactNode<2>> nodes = block_corner_on_elastic_base();
    EXPECT_EQ(marked(
                crosspoint_pairs(nodes, {true, true, true}, no_fixed_dofs())),
              Indices({0}));
    // With the vertical joint compliant the two bedding pairs base-a and
    // base-b act on different block nodes: no redundancy, nothing to
    // mark.
    EXPECT_EQ(marked(
                crosspoint_pairs(nodes, {false, true, true}, no_fixed_dofs())),
              Indices());
  }

  /**
   * Pins down what holds at the elastic-base corner whatever is decided
   * for the test above: the vertical corner pair yields, the last-listed
   * joint (2) keeps both its pairs exact, the pairs away from the corner
   * (y = 0.5, y = 1, x = -0.5) stay exact.
   */
  TEST(Crosspoints, BlockCornerOnElasticBaseMarksVerticalPair)
  {
    const std::vector<ContactNode<2>> nodes = block_corner_on_elastic_base();
    const std::vector<bool>           yields =
      crosspoint_pairs(nodes, {true, true, true}, no_fixed_dofs());
    ASSERT_EQ(yields.size(), nodes.size());
    EXPECT_TRUE(yields[0]);
    for (const unsigned int p : {1u, 2u, 3u, 5u, 6u})
      EXPECT_FALSE(yields[p]) << "pair " << p;
  }

  /**
   * Pins down: compliant joints are never marked and make no crosspoint
   * (is_exact false): with the vertical joint compliant nothing is
   * marked; with the bedding compliant the exact vertical joint keeps
   * its corner pair; with everything compliant on the elastic base
   * nothing is marked.
   */
  TEST(Crosspoints, CompliantJointsAreUntouched)
  {
    for (const auto &is_exact :
         std::vector<std::vector<bool>>{{false, true, true},
                                        {true, false, false}})
      EXPECT_EQ(marked(crosspoint_pairs(block_corner_on_rigid_base(),
                                        is_exact,
                                        no_fixed_dofs())),
                Indices());
    EXPECT_EQ(marked(crosspoint_pairs(block_corner_on_elastic_base(),
                                      {false, false, false},
                                      no_fixed_dofs())),
              Indices());
  }

  /**
   * Pins down the obstacle and fixed nodes as one ground vertex: a pair
   * against the obstacle that shares a node with an exact two-sided pair
   * closes no cycle by itself (the other block's corner is free: four
   * independent constraints), so nothing yields, in either joint order;
   * once the other corner is fixed by a support (both its DoFs Dirichlet,
   * the face block's corner in S6) the two pairs tie one node to the
   * ground twice and the earlier-listed pair yields; with one of the two
   * DoFs fixed the node is no ground vertex.
   */
  TEST(Crosspoints, ObstacleAndFixedNodesAreTheGround)
  {
    const std::vector<ContactNode<2>> face_then_bedding{
      pair(0, {0., 0.}, 0.25, horizontal, corner_l, corner_r),
      pair(0, {0., 0.5}, 0.5, horizontal, middle_l, middle_r),
      obstacle_pair(1, {0., 0.}, 0.25, vertical, corner_r),
      obstacle_pair(1, {0.5, 0.}, 0.25, vertical, bottom_r)};
    EXPECT_EQ(marked(crosspoint_pairs(face_then_bedding,
                                      {true, true},
                                      no_fixed_dofs())),
              Indices());
    EXPECT_EQ(marked(crosspoint_pairs(
                std::vector<ContactNode<2>>{
                  obstacle_pair(0, {0.5, 0.}, 0.25, vertical, bottom_r),
                  obstacle_pair(0, {0., 0.}, 0.25, vertical, corner_r),
                  pair(1, {0., 0.}, 0.25, horizontal, corner_l, corner_r),
                  pair(1, {0., 0.5}, 0.5, horizontal, middle_l, middle_r)},
                {true, true},
                no_fixed_dofs())),
              Indices());

    dealii::IndexSet corner_l_fixed = no_fixed_dofs();
    corner_l_fixed.add_index(dofs_of(corner_l)[0]);
    EXPECT_EQ(
      marked(crosspoint_pairs(face_then_bedding, {true, true}, corner_l_fixed)),
      Indices());
    corner_l_fixed.add_index(dofs_of(corner_l)[1]);
    EXPECT_EQ(
      marked(crosspoint_pairs(face_then_bedding, {true, true}, corner_l_fixed)),
      Indices({0}));
  }
} // namespace
