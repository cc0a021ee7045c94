// The governing joint of each figure (compare/governing_joints.h), on a
// hand-made increment: no FE code runs.
#include <compare/governing_joints.h>

#include <gtest/gtest.h>

using namespace FloorBlock;

namespace
{
  Contact::JointReport
  joint(const std::string &name,
        const double       force,
        const double       peak,
        const double       x,
        const double       y)
  {
    Contact::JointReport report;
    report.name                        = name;
    report.normal_force                = force;
    report.peak_normal_stress          = peak;
    report.averaged_peak_normal_stress = 0.9 * peak;
    report.mean_normal_stress          = 0.5 * peak;
    report.peak_position               = dealii::Point<2>(x, y);
    return report;
  }

  const Compare::GoverningJoint &
  figure(const std::vector<Compare::GoverningJoint> &governing,
         const std::string                          &key)
  {
    for (const auto &entry : governing)
      if (entry.figure == key)
        return entry;
    throw std::runtime_error("no figure " + key);
  }
} // namespace

// The tool shall name the joint with the largest value of each figure, with
// where it sits and the face joint's value beside it; Q among the vertical
// joints only, the stresses among all joints.
TEST(GoverningJoints, LargestOfEachFigureWithItsPlaceAndTheFaceValue)
{
  Contact::IncrementResult increment;
  increment.joints     = {joint("vertical 1", 1e6, 5e6, 2.4, 1.8),
                          joint("vertical 2", 2e6, 21.4e6, 1.2, 1.8),
                          joint("vertical 3", 2.5e6, 17.4e6, 0., 1.8),
                          joint("bedding 2", 9e6, 22.3e6, 1.2, 0.)};
  const auto governing = Compare::governing_joints(increment, 3);
  ASSERT_EQ(governing.size(), 4u);

  const auto &q = figure(governing, "Q_N_per_m");
  EXPECT_EQ(q.joint, "vertical 3"); // bedding 2's larger force is no Q
  EXPECT_TRUE(q.is_face_joint());
  EXPECT_DOUBLE_EQ(q.value, 2.5e6);

  const auto &peak = figure(governing, "sigma_max_Pa");
  EXPECT_EQ(peak.joint, "bedding 2");
  EXPECT_FALSE(peak.is_face_joint());
  EXPECT_DOUBLE_EQ(peak.value, 22.3e6);
  EXPECT_DOUBLE_EQ(peak.x, 1.2);
  EXPECT_DOUBLE_EQ(peak.y, 0.);
  EXPECT_EQ(peak.face_joint, "vertical 3");
  EXPECT_DOUBLE_EQ(peak.face_value, 17.4e6);

  EXPECT_EQ(figure(governing, "sigma_max_averaged_Pa").joint, "bedding 2");
  EXPECT_EQ(figure(governing, "sigma_mean_Pa").joint, "bedding 2");
}

// The tool shall keep the face joint where another joint only ties with it,
// to round-off (unloaded blocks pass Q on unchanged to 1e-12 of it).
TEST(GoverningJoints, TieGoesToTheFaceJoint)
{
  Contact::IncrementResult increment;
  increment.joints = {joint("vertical 1", 3e6 * (1. + 1e-12), 10e6, 1., 2.),
                      joint("vertical 2", 3e6, 10e6, 0., 2.)};
  for (const auto &entry : Compare::governing_joints(increment, 2))
    EXPECT_TRUE(entry.is_face_joint()) << entry.figure;
  EXPECT_TRUE(Compare::governing_joints(Contact::IncrementResult(), 2).empty());
}
