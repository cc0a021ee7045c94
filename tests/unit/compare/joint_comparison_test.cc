// FEM against the closed forms, joint by joint: which joints are compared,
// the relative difference and when it is undefined, the FEM's own floor lift
// from the body rotations, and the load check that keeps round-off out.
#include <analytic/block_chain.h>
#include <analytic/corner_contact.h>
#include <analytic/status.h>
#include <compare/joint_comparison.h>
#include <compare/joint_name.h>
#include <compare/load_check.h>
#include <geometry/ids.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace FloorBlock;
  using Compare::DifferenceStatus;

  // Each expected value is a few operations on exact inputs: round-off only.
  constexpr double tolerance = 1e-12; // relative

  constexpr double youngs_modulus = 16e9; // Pa
  constexpr double support_width  = 1.5;  // m
  constexpr double block_width    = 1.;   // m
  constexpr double block_height   = 2.;   // m

  Contact::JointReport
  joint(const std::string &name,
        const double       normal_force,
        const double       closed_length = 0.)
  {
    Contact::JointReport report;
    report.name          = name;
    report.normal_force  = normal_force;
    report.closed_length = closed_length;
    return report;
  }

  Fem::RigidMotion<2>
  motion(const double translation_x, const double rotation)
  {
    Fem::RigidMotion<2> result;
    result.translation[0] = translation_x;
    result.rotation       = rotation;
    return result;
  }

  /**
   * Two blocks, three mechanisms: no_rotation answers Q = (100, 200) kN/m,
   * rotation_no_vertical_slip keeps (0, 150) kN/m although a joint opens,
   * rotation_vertical_slip has no answer (self-locking, empty vectors).
   */
  Scene::ClosedForms
  two_block_closed_forms()
  {
    Scene::ClosedForms forms;
    forms.chain = Analytic::uniform_chain(
      2, 40e3, 0., 0.1, block_width, block_height, 0.5, 0.5);
    forms.support_width  = support_width;
    forms.youngs_modulus = youngs_modulus;
    forms.floor_lift     = 0.;

    Scene::MechanismResult no_rotation;
    no_rotation.mechanism            = Scene::Mechanism::no_rotation;
    no_rotation.forces.lateral_force = {100e3, 200e3};
    Scene::MechanismResult rotation;
    rotation.mechanism            = Scene::Mechanism::rotation_no_vertical_slip;
    rotation.forces.status        = Analytic::Status::joint_opens;
    rotation.forces.lateral_force = {0., 150e3};
    Scene::MechanismResult locked;
    locked.mechanism     = Scene::Mechanism::rotation_vertical_slip;
    locked.forces.status = Analytic::Status::self_locking;
    forms.mechanisms     = {no_rotation, rotation, locked};
    return forms;
  }

  /** A loaded increment: Q_1 = 110 kN/m, Q_2 = 180 kN/m, blocks rotated. */
  Contact::IncrementResult
  loaded_increment()
  {
    Contact::IncrementResult increment;
    increment.balance.applied_load[1]      = -50e3;
    increment.balance.support_reaction[1]  = 50e3;
    increment.joints                       = {joint("bedding 1", 100e3),
                                              joint("vertical 1", 110e3, 0.5),
                                              joint("bedding 2", 90e3),
                                              joint("vertical 2", 180e3, 0.4)};
    increment.joints[1].peak_normal_stress = 3e6;
    increment.joints[1].averaged_peak_normal_stress = 2.5e6;
    increment.joints[1].mean_normal_stress          = 2e5;
    // The face block does not move: it has no motion entry (rotation 0).
    increment.motions[Geometry::Ids::block_material(1)] = motion(1e-3, 2e-3);
    increment.motions[Geometry::Ids::block_material(2)] = motion(1e-3, 5e-4);
    return increment;
  }

  const Compare::ContactConstants constants{youngs_modulus,
                                            support_width,
                                            block_width,
                                            block_height};

  TEST(JointName, SplitsKindAndNumber)
  {
    const auto vertical = Compare::parse_joint_name("vertical 3");
    EXPECT_EQ(vertical.kind, "vertical");
    EXPECT_EQ(vertical.number, 3u);
    const auto bedding = Compare::parse_joint_name("bedding 12");
    EXPECT_EQ(bedding.kind, "bedding");
    EXPECT_EQ(bedding.number, 12u);
    // A name without a number keeps number 0, which the comparison skips.
    const auto face = Compare::parse_joint_name("face");
    EXPECT_EQ(face.kind, "face");
    EXPECT_EQ(face.number, 0u);
  }

  // The solver names the joint between block n and the face block
  // "vertical n" (Scene::make_floor_contact_problem).
  TEST(JointName, FaceJointIsTheVerticalJointAfterTheLastBlock)
  {
    EXPECT_EQ(Compare::face_joint_name(6), "vertical 6");
    const auto face = Compare::parse_joint_name(Compare::face_joint_name(3));
    EXPECT_EQ(face.kind, "vertical");
    EXPECT_EQ(face.number, 3u);
  }

  TEST(DifferenceStatus, WordsOfEveryStatus)
  {
    EXPECT_EQ(Compare::to_string(DifferenceStatus::defined), "ok");
    EXPECT_EQ(Compare::to_string(DifferenceStatus::no_closed_form),
              "no_closed_form");
    EXPECT_EQ(Compare::to_string(DifferenceStatus::no_load), "no_load");
    EXPECT_EQ(Compare::to_string(DifferenceStatus::zero_closed_form),
              "zero_closed_form");
  }

  // Largest force 180 kN/m (joint 2) against a round-off force of
  // 1e-10 x 16 GPa x 1 mm = 1.6e-3 N/m.
  TEST(LoadCheck, LargestForceAgainstRoundOffOfTheLargestTranslation)
  {
    const Compare::LoadCheck check =
      Compare::check_load(loaded_increment(), youngs_modulus);
    EXPECT_NEAR(check.largest_force, 180e3, tolerance * 180e3);
    EXPECT_NEAR(check.round_off_force, 1.6e-3, tolerance * 1.6e-3);
    EXPECT_TRUE(check.carries_load());
  }

  // A lift that moves the blocks by 1 cm without pressing them: forces of
  // 1 mN/m are below 1e-10 x 16 GPa x 1 cm = 16 mN/m.
  TEST(LoadCheck, RoundOffForcesCarryNoLoad)
  {
    Contact::IncrementResult increment;
    increment.joints = {joint("vertical 1", 1e-3), joint("vertical 2", -1e-3)};
    increment.motions[Geometry::Ids::block_material(1)] = motion(1e-2, 0.);
    const Compare::LoadCheck check =
      Compare::check_load(increment, youngs_modulus);
    EXPECT_NEAR(check.largest_force, 1e-3, tolerance * 1e-3);
    EXPECT_NEAR(check.round_off_force, 16e-3, tolerance * 16e-3);
    EXPECT_FALSE(check.carries_load());
  }

  // Only vertical joints, in the solver's order, each with one record per
  // mechanism: (FEM - closed form) / |closed form| where both exist.
  TEST(JointComparison, RelativeDifferenceOfEveryVerticalJointAndMechanism)
  {
    const auto comparisons =
      Compare::compare_vertical_joints(loaded_increment(),
                                       two_block_closed_forms(),
                                       constants);
    ASSERT_EQ(comparisons.size(), 2u);
    EXPECT_EQ(comparisons[0].joint, 1u);
    EXPECT_EQ(comparisons[1].joint, 2u);
    EXPECT_EQ(comparisons[0].fem_force, 110e3);
    EXPECT_EQ(comparisons[1].fem_force, 180e3);
    for (const auto &comparison : comparisons)
      {
        ASSERT_EQ(comparison.forces.size(), 3u);
        EXPECT_TRUE(comparison.load.carries_load());
      }

    // Joint 1: (110 - 100) / 100 against no_rotation; rotation's 0 has no
    // relative difference.
    const auto &first = comparisons[0].forces;
    EXPECT_EQ(first[0].mechanism, "no_rotation");
    EXPECT_EQ(first[0].difference_status, DifferenceStatus::defined);
    EXPECT_NEAR(first[0].relative_difference, 0.1, tolerance);
    EXPECT_EQ(first[1].mechanism, "rotation_no_vertical_slip");
    EXPECT_TRUE(first[1].has_value);
    EXPECT_EQ(first[1].difference_status, DifferenceStatus::zero_closed_form);
    EXPECT_EQ(first[1].relative_difference, 0.);

    // Joint 2: (180 - 200) / 200 and (180 - 150) / 150; the closed form's
    // own status travels with its value.
    const auto &second = comparisons[1].forces;
    EXPECT_NEAR(second[0].relative_difference, -0.1, tolerance);
    EXPECT_EQ(second[1].closed_form_status, Analytic::Status::joint_opens);
    EXPECT_EQ(second[1].status,
              Analytic::to_string(Analytic::Status::joint_opens));
    EXPECT_EQ(second[1].difference_status, DifferenceStatus::defined);
    EXPECT_NEAR(second[1].relative_difference, 0.2, tolerance);

    // A mechanism without values is never compared.
    for (const auto &comparison : comparisons)
      {
        const auto &locked = comparison.forces[2];
        EXPECT_EQ(locked.mechanism, "rotation_vertical_slip");
        EXPECT_EQ(locked.closed_form_status, Analytic::Status::self_locking);
        EXPECT_FALSE(locked.has_value);
        EXPECT_EQ(locked.difference_status, DifferenceStatus::no_closed_form);
        EXPECT_EQ(locked.relative_difference, 0.);
      }
  }

  // Eq. 6.51 with the FEM's own inputs: y = L tan(theta_j - theta_{j+1}),
  // the face block (no motion) counting as unrotated, and Q over b.
  TEST(JointComparison, CornerContactUsesTheFemsOwnLiftAndForce)
  {
    const auto comparisons =
      Compare::compare_vertical_joints(loaded_increment(),
                                       two_block_closed_forms(),
                                       constants);
    ASSERT_EQ(comparisons.size(), 2u);

    const Compare::ContactComparison &inner = comparisons[0].contact;
    EXPECT_NEAR(inner.relative_rotation, 1.5e-3, tolerance * 1.5e-3);
    EXPECT_NEAR(inner.floor_lift, std::tan(1.5e-3), tolerance * 1.5e-3);
    EXPECT_NEAR(inner.force_over_width, 165e3, tolerance * 165e3);
    EXPECT_NEAR(inner.fem_area, 0.75, tolerance);
    EXPECT_EQ(inner.fem_peak_stress, 3e6);
    EXPECT_EQ(inner.fem_averaged_peak_stress, 2.5e6);
    EXPECT_EQ(inner.fem_mean_stress, 2e5);
    EXPECT_TRUE(inner.fem_carries_load);
    // 6.51 by hand: c = L sqrt(2 Q / (y E b)), sigma_max = 2 Q / (b c).
    const double y = std::tan(1.5e-3);
    const double c =
      std::sqrt(2. * 165e3 / (y * youngs_modulus * support_width));
    ASSERT_EQ(inner.closed_form.status, Analytic::Status::ok);
    EXPECT_NEAR(inner.closed_form.contact_length, c, 1e-10 * c);
    EXPECT_NEAR(inner.closed_form.max_stress,
                2. * 165e3 / (support_width * c),
                1e-10 * inner.closed_form.max_stress);

    const Compare::ContactComparison &face = comparisons[1].contact;
    EXPECT_NEAR(face.relative_rotation, 5e-4, tolerance * 5e-4);
    EXPECT_NEAR(face.floor_lift, std::tan(5e-4), tolerance * 5e-4);
    EXPECT_NEAR(face.fem_area, 0.6, tolerance);
  }

  // A relative rotation that opens the top corners gives y < 0: the closed
  // form reports zero_floor_lift; a joint in tension presses with Q = 0.
  TEST(JointComparison, OpeningRotationAndTensionAreReportedNotCompared)
  {
    Contact::IncrementResult increment                  = loaded_increment();
    increment.motions[Geometry::Ids::block_material(1)] = motion(1e-3, -1e-3);
    increment.joints[1].normal_force                    = -5e3;
    const auto comparisons =
      Compare::compare_vertical_joints(increment,
                                       two_block_closed_forms(),
                                       constants);
    ASSERT_EQ(comparisons.size(), 2u);
    const Compare::ContactComparison &inner = comparisons[0].contact;
    EXPECT_LT(inner.floor_lift, 0.);
    EXPECT_EQ(inner.force_over_width, 0.);
    EXPECT_EQ(inner.closed_form.status, Analytic::Status::zero_floor_lift);
  }

  // Round-off forces are not compared: every value is marked no_load.
  TEST(JointComparison, UnloadedIncrementIsNotCompared)
  {
    Contact::IncrementResult increment;
    increment.joints = {joint("vertical 1", 1e-3), joint("vertical 2", 2e-3)};
    increment.motions[Geometry::Ids::block_material(1)] = motion(1e-2, 0.);
    const auto comparisons =
      Compare::compare_vertical_joints(increment,
                                       two_block_closed_forms(),
                                       constants);
    ASSERT_EQ(comparisons.size(), 2u);
    for (const auto &comparison : comparisons)
      {
        EXPECT_FALSE(comparison.load.carries_load());
        EXPECT_FALSE(comparison.contact.fem_carries_load);
        EXPECT_EQ(comparison.forces[0].difference_status,
                  DifferenceStatus::no_load);
        EXPECT_EQ(comparison.forces[0].relative_difference, 0.);
        EXPECT_EQ(comparison.forces[2].difference_status,
                  DifferenceStatus::no_closed_form);
      }
  }
} // namespace
