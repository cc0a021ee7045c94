// Issue 16: the joint reports of a 3D joint swept along the face, per
// metre of face, with the contact area as an area.
#include <gtest/gtest.h>
#include <postprocess/swept_joint_report.h>

#include <vector>

namespace
{
  using namespace FloorBlock;

  constexpr double traction = 1e6; // Pa, compression

  /**
   * A vertical joint x = 0, 1 m tall (five nodes, 0.25 m apart), swept
   * over 1 m of face in two slices: sections at z = 0, 0.5, 1 standing
   * for 0.25, 0.5 and 0.25 m of face. The sections listed in
   * @p closed_sections press with @p traction along the whole joint, the
   * others are open by 1 mm.
   */
  void
  make_joint(const std::vector<bool>                &closed_sections,
             std::vector<Contact::ContactNode<3>>   &nodes,
             std::vector<Contact::JointResponse<3>> &responses)
  {
    const double section_length[3] = {0.25, 0.5, 0.25};
    const double line_weight[5]    = {0.125, 0.25, 0.25, 0.25, 0.125};
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int i = 0; i < 5; ++i)
        {
          Contact::ContactNode<3> node;
          node.joint    = 0;
          node.position = dealii::Point<3>(0., 0.25 * i, 0.5 * k);
          node.weight   = line_weight[i] * section_length[k];
          node.normal   = dealii::Tensor<1, 3>({1., 0., 0.});
          Contact::JointResponse<3> response;
          if (closed_sections[k])
            {
              response.state             = Contact::JointState::stick;
              response.normal_traction   = traction;
              response.closure_stiffness = 1e10;
              response.force_density     = -traction * node.normal;
            }
          else
            response.gap = 1e-3;
          nodes.push_back(node);
          responses.push_back(response);
        }
  }

  // The tool shall report a swept joint's normal force per metre of face
  // (its total over the face length), its contact area (each section's
  // closed length times the length of face it stands for) and contact
  // length = area / face length: sections z = 0 and 0.5 closed over the
  // whole 1 m joint, z = 1 open give 0.25 + 0.5 = 0.75 m^2, 0.75 MN/m.
  TEST(SweptJointReport, AreaAndForcePerMetreFromTheSections)
  {
    std::vector<Contact::ContactNode<3>>   nodes;
    std::vector<Contact::JointResponse<3>> responses;
    make_joint({true, true, false}, nodes, responses);
    const auto reports = Postprocess::make_swept_joint_reports(
      nodes, responses, {"vertical 1"}, 0.1, 1.);
    ASSERT_EQ(reports.size(), 1u);
    const Contact::JointReport &report = reports.front();
    EXPECT_TRUE(report.swept());
    EXPECT_DOUBLE_EQ(report.face_length, 1.);
    EXPECT_NEAR(report.normal_force, 0.75 * traction, 1e-9 * traction);
    EXPECT_NEAR(report.closed_length * report.face_length, 0.75, 1e-12);
    EXPECT_NEAR(report.mean_normal_stress, traction, 1e-9 * traction);
    EXPECT_DOUBLE_EQ(report.peak_normal_stress, traction);
    EXPECT_EQ(report.counts.n_stick, 10u);
    EXPECT_EQ(report.counts.n_open, 5u);
    // The profile is the middle section's (z = 0.5), closed.
    ASSERT_EQ(report.profile.size(), 5u);
    EXPECT_EQ(report.profile.front().state, Contact::JointState::stick);
  }

  // The tool shall report a swept joint section by section along the
  // face: each section's z, the face it stands for (between the midpoints
  // to its neighbours: 0-0.25, 0.25-0.75, 0.75-1 m), its normal force per
  // metre and contact length; the joint's figures are their weighted sums.
  TEST(SweptJointReport, AlongTheFaceSectionBySection)
  {
    std::vector<Contact::ContactNode<3>>   nodes;
    std::vector<Contact::JointResponse<3>> responses;
    make_joint({true, true, false}, nodes, responses);
    const auto report = Postprocess::make_swept_joint_reports(
                          nodes, responses, {"vertical 1"}, 0.1, 1.)
                          .front();
    ASSERT_EQ(report.along_face.size(), 3u);
    const double z[3]      = {0., 0.5, 1.};
    const double z_from[3] = {0., 0.25, 0.75};
    const double z_to[3]   = {0.25, 0.75, 1.};
    double       force = 0., area = 0.;
    for (unsigned int k = 0; k < 3; ++k)
      {
        const Contact::JointSection &section = report.along_face[k];
        EXPECT_DOUBLE_EQ(section.z, z[k]);
        EXPECT_DOUBLE_EQ(section.z_from, z_from[k]);
        EXPECT_DOUBLE_EQ(section.z_to, z_to[k]);
        const bool closed = k < 2;
        EXPECT_NEAR(section.normal_force,
                    closed ? traction : 0.,
                    1e-9 * traction);
        EXPECT_NEAR(section.closed_length, closed ? 1. : 0., 1e-12);
        EXPECT_DOUBLE_EQ(section.peak_normal_stress, closed ? traction : 0.);
        force += (section.z_to - section.z_from) * section.normal_force;
        area += (section.z_to - section.z_from) * section.closed_length;
      }
    EXPECT_NEAR(force,
                report.normal_force * report.face_length,
                1e-9 * traction);
    EXPECT_NEAR(area, report.closed_length * report.face_length, 1e-12);
  }

  // All sections alike (plane strain): the per-metre figures are any one
  // section's, whatever the face length.
  TEST(SweptJointReport, UniformSectionsGiveTheSectionAnswer)
  {
    std::vector<Contact::ContactNode<3>>   nodes;
    std::vector<Contact::JointResponse<3>> responses;
    make_joint({true, true, true}, nodes, responses);
    const auto report = Postprocess::make_swept_joint_reports(
                          nodes, responses, {"vertical 1"}, 0.1, 1.)
                          .front();
    EXPECT_NEAR(report.normal_force, traction, 1e-9 * traction);
    EXPECT_NEAR(report.closed_length, 1., 1e-12);
    EXPECT_NEAR(report.averaged_peak_normal_stress, traction, 1e-9 * traction);
  }
} // namespace
