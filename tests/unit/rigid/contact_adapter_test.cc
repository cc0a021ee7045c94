// RigidBlocks::to_contact_result(): the rigid-block results in the contact
// FEM's structures. Checked on the lifted-parabola scene (6 blocks, 650 t
// on blocks 1-3, flat bedding bent into y = x^2/400): every joint's numbers
// carried over (names, forces, lengths, counts; shear in the FEM's sign),
// block motions under their material ids, the force balance, and the peaks
// computed with the FEM's definition against values derived by hand.

#include <geometry/ids.h>
#include <rigid/contact_adapter.h>

#include <gtest/gtest.h>

#include <cmath>

#include "scene_fixture.h"

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    constexpr unsigned int n_uplift_steps   = 4;
    constexpr double       averaging_length = 0.05; // m, Solver default

    struct AdaptedSolve
    {
      ModelDescription     description;
      Model                model;
      RigidSolveResult     rigid;
      Contact::SolveResult contact;
    };

    ModelDescription
    scene_with_all_profiles()
    {
      ModelDescription description =
        Testing::lifted_parabola_scene(n_uplift_steps);
      description.solver.profiles_of_every_increment = true;
      return description;
    }

    const AdaptedSolve &
    adapted()
    {
      static const AdaptedSolve solve = [] {
        const ModelDescription description = scene_with_all_profiles();
        const Model            model(description);
        const RigidSolveResult rigid = model.solve();
        return AdaptedSolve{description,
                            model,
                            rigid,
                            to_contact_result(rigid, model, averaging_length)};
      }();
      return solve;
    }
  } // namespace

  // The tool shall carry every joint's numbers of every increment over to
  // the FEM's structures, with the FEM's shear sign.
  TEST(ContactAdapter, JointsCarriedOver)
  {
    const AdaptedSolve &solve = adapted();
    ASSERT_EQ(solve.rigid.status, SolveStatus::converged);
    ASSERT_EQ(solve.contact.increments.size(), solve.rigid.increments.size());
    for (unsigned int k = 0; k < solve.rigid.increments.size(); ++k)
      {
        const IncrementReport          &rigid   = solve.rigid.increments[k];
        const Contact::IncrementResult &contact = solve.contact.increments[k];
        EXPECT_EQ(contact.stage, rigid.stage);
        EXPECT_EQ(contact.n_newton_iterations, rigid.n_iterations);
        ASSERT_EQ(contact.joints.size(), rigid.joints.size());
        for (unsigned int j = 0; j < rigid.joints.size(); ++j)
          {
            const RigidJointReport     &from = rigid.joints[j];
            const Contact::JointReport &to   = contact.joints[j];
            EXPECT_EQ(to.name, from.name);
            EXPECT_EQ(to.normal_force, from.normal_force);
            EXPECT_EQ(to.closed_length, from.contact_length);
            EXPECT_EQ(to.mean_normal_stress, from.mean_normal_traction);
            EXPECT_EQ(to.counts.n_stick, from.counts.n_stick);
            EXPECT_EQ(to.counts.n_slip, from.counts.n_slip);
            EXPECT_EQ(to.counts.n_open, from.counts.n_open);
            // FEM tangent (-n_y, n_x) with n from block j+1 into block j
            // is up: the chapter's V_j. On the bedding n points from the
            // base into the block, the tangent towards the face, opposite
            // to the rigid model's sense.
            EXPECT_EQ(to.shear_force,
                      from.kind == JointKind::vertical ? from.shear_force :
                                                         -from.shear_force);
            EXPECT_EQ(to.averaging_length, averaging_length);
          }
      }
    // 6 vertical joints, then 6 bedding joints, named as the FEM names them.
    const auto &last = solve.contact.increments.back();
    EXPECT_EQ(last.joints.front().name, "vertical 1");
    EXPECT_EQ(last.joints[5].name, "vertical 6");
    EXPECT_EQ(last.joints[6].name, "bedding 1");
    EXPECT_EQ(last.stage, Loading::LoadStage::uplift);
    EXPECT_EQ(last.stage_factor, 1.);
    EXPECT_EQ(solve.contact.n_dofs, 3u * 6u);
    EXPECT_EQ(solve.contact.n_contact_pairs, 0u);
    EXPECT_EQ(solve.contact.wall_times.count("Rigid blocks: solve"), 1u);
  }

  // The tool shall report block motions under the mesh's material ids: block
  // i as material i, the fixed face block with zero motion, no base.
  TEST(ContactAdapter, MotionsByMaterialId)
  {
    const AdaptedSolve &solve   = adapted();
    const auto         &rigid   = solve.rigid.increments.back().motions;
    const auto         &motions = solve.contact.increments.back().motions;
    ASSERT_EQ(motions.size(), rigid.size() + 1);
    for (unsigned int i = 1; i <= rigid.size(); ++i)
      {
        const auto &motion = motions.at(Geometry::Ids::block_material(i));
        EXPECT_EQ(motion.rotation, rigid[i - 1].rotation);
        EXPECT_EQ(motion.translation, rigid[i - 1].translation);
      }
    const auto &face = motions.at(Geometry::Ids::face_block_material);
    EXPECT_EQ(face.rotation, 0.);
    EXPECT_EQ(face.translation.norm(), 0.);
    EXPECT_EQ(motions.count(Geometry::Ids::base_material), 0u);
  }

  // The tool shall carry the force balance over: the applied load is the
  // blocks' weight and support loads, the reaction (face block and base on
  // the blocks) balances it, and the per-block imbalance is the rigid one.
  TEST(ContactAdapter, ForceBalanceCarriedOver)
  {
    const AdaptedSolve &solve      = adapted();
    const auto         &d          = solve.description;
    double              total_load = 0.;
    for (const double load : d.support_line_loads)
      total_load += load;
    total_load += d.assembly.n_blocks * d.density * d.gravity *
                  d.assembly.block_width * d.assembly.block_height;
    for (unsigned int k = 0; k < solve.rigid.increments.size(); ++k)
      {
        const auto &balance = solve.contact.increments[k].balance;
        EXPECT_EQ(balance.relative_imbalance,
                  solve.rigid.increments[k].relative_imbalance);
        // The whole assembly is in equilibrium as every block is (1e-8:
        // the rigid model's measured per-block balance, src/rigid/README.md).
        EXPECT_LE((balance.applied_load + balance.support_reaction).norm(),
                  1e-8 * balance.applied_load.norm());
      }
    // After the support stage both loads act in full, straight down.
    const auto &final = solve.contact.increments.back().balance;
    EXPECT_NEAR(final.applied_load[1], -total_load, 1e-12 * total_load);
    EXPECT_EQ(final.applied_load[0], 0.);
  }

  // The tool shall compute the peaks of a rigid joint with the FEM's
  // definition: the pointwise peak and its point as the rigid model found
  // them; a window covering the whole joint gives Q / H; a window w at the
  // top of the face joint's triangular traction gives sigma (1 - w/(2c)).
  TEST(ContactAdapter, PeaksWithTheFemDefinition)
  {
    const AdaptedSolve    &solve        = adapted();
    const IncrementReport &rigid_last   = solve.rigid.increments.back();
    const auto            &contact_last = solve.contact.increments.back();
    for (unsigned int j = 0; j < rigid_last.joints.size(); ++j)
      {
        const RigidJointReport     &from = rigid_last.joints[j];
        const Contact::JointReport &to   = contact_last.joints[j];
        EXPECT_EQ(to.peak_normal_stress, from.peak_normal_traction);
        EXPECT_LE(to.averaged_peak_normal_stress,
                  to.peak_normal_stress * (1. + 1e-14));
        if (from.peak_normal_traction > 0.)
          for (const ProfilePoint &point : from.profile)
            if (point.coordinate == from.peak_coordinate)
              {
                EXPECT_EQ(to.peak_position, point.position) << from.name;
              }
      }

    const double block_height = solve.description.assembly.block_height;
    const Contact::SolveResult whole_joint =
      to_contact_result(solve.rigid, solve.model, 10. * block_height);
    for (const auto &joint : whole_joint.increments.back().joints)
      if (joint.name.rfind("vertical", 0) == 0)
        {
          EXPECT_NEAR(joint.averaged_peak_normal_stress,
                      joint.normal_force / block_height,
                      1e-12 * joint.peak_normal_stress)
            << joint.name;
        }

    // Face joint: linear traction sigma (1 - z/c) below floor level (the
    // Winkler overlap of a rotated rigid face, winkler_test.cc), so the mean
    // over [0, w] is sigma (1 - w/(2c)); the traction falls with depth, so
    // the top window is the largest. The definition spreads each point's
    // value over its tributary interval (half a spacing h at the top
    // end): exact for a linear traction on a symmetric interval, off by
    // sigma h^2/(8c) on the top half interval and by at most sigma h^2/(4c)
    // on the interval cut by the window end. Bound on the mean:
    // 3 sigma h^2 / (8 c w), 7e-4 sigma for h = 5 mm, c = 0.29 m.
    const Contact::JointReport &face = contact_last.joints[5];
    ASSERT_EQ(face.name, "vertical 6");
    const double contact = face.closed_length;
    ASSERT_GT(contact, averaging_length);
    const double spacing =
      block_height / (solve.description.solver.n_points_per_joint - 1);
    EXPECT_NEAR(face.averaged_peak_normal_stress,
                face.peak_normal_stress *
                  (1. - averaging_length / (2. * contact)),
                3. * spacing * spacing / (8. * contact * averaging_length) *
                  face.peak_normal_stress);
  }
} // namespace FloorBlock::RigidBlocks
