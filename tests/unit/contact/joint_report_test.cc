// Joint post-processing without a mesh: a linear pressure profile along a
// straight joint has closed-form force, closed length and window average.
#include <contact/joint_report.h>

#include <gtest/gtest.h>

namespace
{
  using namespace FloorBlock::Contact;

  TEST(JointReport, LinearProfileHasExactForceAndWindowAverage)
  {
    constexpr unsigned int n_cells     = 10;
    constexpr double       length      = 1.;  // m
    constexpr double       peak        = 1e6; // Pa at s = 0
    constexpr double       window      = 0.2; // m
    const double           spacing     = length / n_cells;
    std::vector<ContactNode<2>>   nodes;
    std::vector<JointResponse<2>> responses;
    for (unsigned int k = 0; k <= n_cells; ++k)
      {
        ContactNode<2> node;
        node.position  = dealii::Point<2>(0., k * spacing); // vertical joint
        node.normal[0] = 1.;
        node.weight    = (k == 0 || k == n_cells) ? spacing / 2. : spacing;
        nodes.push_back(node);
        JointResponse<2> response;
        response.state           = JointState::stick;
        response.normal_traction = peak * (1. - k * spacing / length);
        responses.push_back(response);
      }
    const JointReport report =
      make_joint_reports(nodes, responses, {"joint"}, window).at(0);
    // Lumped weights integrate a linear profile exactly (trapezoidal rule).
    EXPECT_NEAR(report.normal_force, peak * length / 2., 1e-12 * peak);
    EXPECT_NEAR(report.closed_length, length, 1e-12);
    EXPECT_NEAR(report.peak_normal_stress, peak, 1e-12 * peak);
    EXPECT_NEAR(report.peak_position[1], 0., 1e-15);
    // Best window is [0, 0.2]: mean of the linear profile = peak (1 - 0.1).
    // Piecewise-constant tributaries integrate it exactly here because the
    // window edges fall on tributary midpoints symmetric about nodes.
    EXPECT_NEAR(report.averaged_peak_normal_stress, 0.9 * peak, 1e-12 * peak);
    EXPECT_NEAR(report.mean_normal_stress, peak / 2., 1e-12 * peak);
  }
} // namespace
