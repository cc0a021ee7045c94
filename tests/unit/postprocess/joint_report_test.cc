// Joint post-processing without a mesh: a linear pressure profile along a
// straight joint has closed-form force, closed length and window average;
// synthetic gap and pressure profiles, evaluated with the real joint law,
// have a known interpolated contact end.
#include <contact/joint_law.h>

#include <gtest/gtest.h>
#include <postprocess/joint_report.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

namespace
{
  using namespace FloorBlock::Contact;
  using namespace FloorBlock::Postprocess;

  TEST(JointReport, LinearProfileHasExactForceAndWindowAverage)
  {
    constexpr unsigned int        n_cells = 10;
    constexpr double              length  = 1.;  // m
    constexpr double              peak    = 1e6; // Pa at s = 0
    constexpr double              window  = 0.2; // m
    const double                  spacing = length / n_cells;
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

  constexpr double normal_stiffness = 1e10; // Pa/m, compliant joint
  constexpr double rigid_penalty    = 1e12; // Pa/m, augmentation

  CoulombJoint<2>
  make_law(const double stiffness, const double tensile_strength = 0.)
  {
    JointConstants parameters;
    parameters.normal_stiffness = stiffness;
    parameters.shear_stiffness  = stiffness / 2.;
    parameters.friction_angle   = std::atan(0.6);
    parameters.tensile_strength = tensile_strength;
    return CoulombJoint<2>(parameters);
  }

  dealii::Tensor<1, 2>
  joint_normal()
  {
    dealii::Tensor<1, 2> normal;
    normal[0] = 1.;
    return normal;
  }

  /** Pair history of the law for a normal multiplier (rigid law). */
  JointHistory<2>
  with_multiplier(const double multiplier)
  {
    JointHistory<2> history;
    history.normal_base = multiplier;
    return history;
  }

  /**
   * Nodes of a vertical joint at the given heights (any order), weights
   * half of the adjacent cells, each evaluated with @p law at the gap and
   * history that @p state_at gives for its height.
   */
  JointReport
  report_of(
    const std::vector<double>                                       &heights,
    const CoulombJoint<2>                                           &law,
    const std::function<std::pair<double, JointHistory<2>>(double)> &state_at)
  {
    std::vector<double> sorted = heights;
    std::sort(sorted.begin(), sorted.end());
    std::vector<ContactNode<2>>   nodes;
    std::vector<JointResponse<2>> responses;
    for (const double height : heights)
      {
        const auto     at    = std::find(sorted.begin(), sorted.end(), height);
        const double   below = at == sorted.begin() ? height : *(at - 1);
        const double   above = at + 1 == sorted.end() ? height : *(at + 1);
        ContactNode<2> node;
        node.position = dealii::Point<2>(0., height);
        node.normal   = joint_normal();
        node.weight   = (above - below) / 2.;
        nodes.push_back(node);
        const auto [gap, history] = state_at(height);
        responses.push_back(
          law.evaluate(gap * joint_normal(), joint_normal(), history));
      }
    return make_joint_reports(nodes, responses, {"joint"}, 0.05).at(0);
  }

  /** 0, 0.1, ..., 1 m. */
  std::vector<double>
  uniform_heights()
  {
    std::vector<double> heights;
    for (unsigned int k = 0; k <= 10; ++k)
      heights.push_back(0.1 * k);
    return heights;
  }

  TEST(JointReport, IndicatorIsMinusTheGapOfTheCompliantLawOnBothSides)
  {
    const CoulombJoint<2> law = make_law(normal_stiffness);
    const double          gap = 2e-5; // m
    dealii::Tensor<1, 2>  slide;
    slide[1]         = 1e-2; // m, far beyond the stick limit
    const auto open  = law.evaluate(gap * joint_normal(), joint_normal(), {});
    const auto stuck = law.evaluate(-gap * joint_normal(), joint_normal(), {});
    const auto sliding =
      law.evaluate(-gap * joint_normal() + slide, joint_normal(), {});
    ASSERT_EQ(open.state, JointState::open);
    ASSERT_EQ(stuck.state, JointState::stick);
    ASSERT_EQ(sliding.state, JointState::slip);
    EXPECT_DOUBLE_EQ(contact_indicator(open), -gap);
    EXPECT_DOUBLE_EQ(contact_indicator(stuck), gap);
    // The slip tangent's friction term e (x) n has no n-n part.
    EXPECT_DOUBLE_EQ(contact_indicator(sliding), gap);
  }

  TEST(JointReport, IndicatorOfTheRigidLawIsMultiplierOverPenaltyMinusGap)
  {
    const CoulombJoint<2> law        = make_law(rigid_penalty);
    const double          multiplier = 3e6;  // Pa
    const double          gap        = 1e-7; // m, below multiplier/penalty
    const auto            closed     = law.evaluate(gap * joint_normal(),
                                     joint_normal(),
                                     with_multiplier(multiplier));
    ASSERT_EQ(closed.state, JointState::stick);
    // t_n = 3e6 - 1e12 * 1e-7 = 2.9e6 Pa, phi = t_n / penalty = 2.9e-6 m.
    EXPECT_NEAR(contact_indicator(closed),
                multiplier / rigid_penalty - gap,
                1e-12 * gap);
  }

  TEST(JointReport, CompliantContactEndsWhereTheLinearGapVanishes)
  {
    // g(y) = slope (y - end): closed (overlap) below end, open above; the
    // indicator is -g at every node, its interpolant is g itself, so the
    // closed length is exactly `end`. The node measure would give the
    // weights of nodes 0..0.4 m: 0.45 m.
    const CoulombJoint<2> law   = make_law(normal_stiffness);
    const double          slope = 1e-3;  // m of gap per m of joint
    const double          end   = 0.437; // m
    const JointReport     report =
      report_of(uniform_heights(), law, [&](const double height) {
        return std::make_pair(slope * (height - end), JointHistory<2>());
      });
    EXPECT_EQ(report.counts.n_open, 6u);
    EXPECT_NEAR(report.closed_length, end, 1e-12);
    EXPECT_NEAR(report.mean_normal_stress,
                report.normal_force / end,
                1e-12 * report.normal_force);
    // The second end rule (a quadratic through one more open node) agrees
    // on a linear gap: no location uncertainty.
    EXPECT_NEAR(report.closed_length_uncertainty, 0., 1e-12);
  }

  // The tool shall state how uncertain an interpolated contact end is.
  // g(y) = slope (y - end) + curvature (y - end)^2: the linear rule misses
  // `end` by O(h^2 curvature / slope), the quadratic through the open node
  // beyond finds it exactly, so the uncertainty is the linear rule's error.
  TEST(JointReport, EndUncertaintyIsTheLinearRulesErrorOnAQuadraticGap)
  {
    const CoulombJoint<2> law       = make_law(normal_stiffness);
    const double          slope     = 1e-3;
    const double          curvature = 2e-3; // m of gap per m^2
    const double          end       = 0.437;
    const JointReport     report =
      report_of(uniform_heights(), law, [&](const double height) {
        const double d = height - end;
        return std::make_pair(slope * d + curvature * d * d, JointHistory<2>());
      });
    const double linear_error = std::abs(report.closed_length - end);
    EXPECT_GT(linear_error, 1e-3) << "the test needs a visible miss";
    EXPECT_NEAR(report.closed_length_uncertainty, linear_error, 1e-12);
  }

  TEST(JointReport, ContactEndOnGradedUnorderedNodes)
  {
    // Same linear gap on a graded joint whose nodes arrive out of order:
    // the sort by arc position and the weight shares give `end` again.
    const CoulombJoint<2> law   = make_law(normal_stiffness);
    const double          slope = 1e-3;
    const double          end   = 0.61;
    const JointReport     report =
      report_of({1., 0.05, 0.55, 0., 0.3, 0.8, 0.15, 0.58},
                law,
                [&](const double height) {
                  return std::make_pair(slope * (height - end),
                                        JointHistory<2>());
                });
    EXPECT_NEAR(report.closed_length, end, 1e-12);
  }

  TEST(JointReport, ClosedLengthIsContinuousAsTheEndCrossesNodes)
  {
    // The node measure jumps by 0.1 m at y = 0.4 and 0.95 m; the
    // interpolated one follows `end`, through nodes and up to the joint's
    // end (beyond it every node is closed: the joint length).
    const CoulombJoint<2> law   = make_law(normal_stiffness);
    const double          slope = 1e-3;
    for (const double end : {0.4 - 1e-9, 0.4, 0.4 + 1e-9, 0.95, 1. - 1e-9})
      {
        const JointReport report =
          report_of(uniform_heights(), law, [&](const double height) {
            return std::make_pair(slope * (height - end), JointHistory<2>());
          });
        EXPECT_NEAR(report.closed_length, end, 1e-12) << "end " << end;
      }
  }

  TEST(JointReport, RigidContactEndBetweenPressureAndGap)
  {
    // Converged augmented Lagrangian: closed pairs with zero gap carry the
    // multiplier p(y) = penalty * pressure_slope * (end - y), open pairs
    // none and a gap g(y) = gap_slope * (y - end). Indicator: closed
    // pressure_slope (end - y), open -gap_slope (y - end). Between the
    // closed node y_c = 0.4 and the open node y_o = 0.5 its interpolant
    // vanishes at y_c + (y_o - y_c) phi_c / (phi_c - phi_o)
    // = 0.4 + 0.1 * 3.7e-6 / (3.7e-6 + 6.3e-5) = 0.40554723 m: the slopes
    // differ, so the end lies closer to the node with the smaller |phi|.
    const CoulombJoint<2> law            = make_law(rigid_penalty);
    const double          pressure_slope = 1e-4; // (Pa / penalty) per m
    const double          gap_slope      = 1e-3; // m per m
    const double          end            = 0.437;
    const JointReport     report =
      report_of(uniform_heights(), law, [&](const double height) {
        const double multiplier =
          rigid_penalty * pressure_slope * (end - height);
        if (height < end)
          return std::make_pair(0., with_multiplier(multiplier));
        return std::make_pair(gap_slope * (height - end), JointHistory<2>());
      });
    const double closed_indicator = pressure_slope * (end - 0.4);
    const double open_indicator   = -gap_slope * (0.5 - end);
    EXPECT_NEAR(report.closed_length,
                0.4 +
                  0.1 * closed_indicator / (closed_indicator - open_indicator),
                1e-12);
    EXPECT_NEAR(report.closed_length, 0.40554723, 1e-8);
  }

  // Exact-law tractions fall like the square root of the distance to the
  // end: p = A sqrt(end - y) below the end, open above. t_n^2 is linear
  // in y, so its extrapolation from the last two closed nodes finds the
  // end exactly, wherever it lies between the nodes; the linear indicator
  // rule would not (it needs the gap scale).
  TEST(JointReport, ExactTractionEndsWhereItsSquareVanishes)
  {
    constexpr unsigned int n_cells = 10;
    constexpr double       spacing = 0.1; // m
    for (const double end : {0.4001, 0.437, 0.45, 0.4999})
      {
        std::vector<ContactNode<2>>   nodes;
        std::vector<JointResponse<2>> responses;
        for (unsigned int k = 0; k <= n_cells; ++k)
          {
            const double   height = k * spacing;
            ContactNode<2> node;
            node.position  = dealii::Point<2>(0., height);
            node.normal[0] = 1.;
            node.weight    = (k == 0 || k == n_cells) ? spacing / 2. : spacing;
            nodes.push_back(node);
            JointResponse<2> response;
            response.exact_traction    = true;
            response.closure_stiffness = 1e11;
            if (height < end)
              {
                response.state           = JointState::stick;
                response.normal_traction = 1e7 * std::sqrt(end - height);
              }
            else
              response.gap = 1e-4 * std::pow(height - end, 1.5);
            responses.push_back(response);
          }
        const JointReport report =
          make_joint_reports(nodes, responses, {"joint"}, 0.05).at(0);
        EXPECT_NEAR(report.closed_length, end, 1e-12) << "end " << end;
        // t_n^2 from the next two closed nodes is the same line.
        EXPECT_NEAR(report.closed_length_uncertainty, 0., 1e-9)
          << "end " << end;
      }
  }

  TEST(JointReport, MidJointOpeningHasTwoInterpolatedEnds)
  {
    // g(y) = gap - slope |y - 0.5|: open for |y - 0.5| < gap / slope =
    // 0.137 m, closed outside. The kink sits on the node y = 0.5, so the
    // nodal interpolant is g itself: closed length 1 - 2 * 0.137 m.
    const CoulombJoint<2> law       = make_law(normal_stiffness);
    const double          slope     = 1e-3;
    const double          half_open = 0.137;
    const JointReport     report =
      report_of(uniform_heights(), law, [&](const double height) {
        return std::make_pair(slope * (half_open - std::abs(height - 0.5)),
                              JointHistory<2>());
      });
    EXPECT_EQ(report.counts.n_open, 3u);
    EXPECT_NEAR(report.closed_length, 1. - 2. * half_open, 1e-12);
  }

  TEST(JointReport, AllClosedAndAllOpenKeepTheNodeMeasure)
  {
    const CoulombJoint<2>     law     = make_law(normal_stiffness);
    const std::vector<double> heights = {0., 0.13, 0.3, 0.62, 1.};
    const JointReport closed = report_of(heights, law, [](const double height) {
      return std::make_pair(-1e-5 * (1. + height), JointHistory<2>());
    });
    const JointReport open   = report_of(heights, law, [](const double height) {
      return std::make_pair(1e-5 * (1. + height), JointHistory<2>());
    });
    // The weights report_of() gives, added in arc order as the node
    // measure adds them (heights are sorted).
    double weight_sum = 0.;
    for (unsigned int k = 0; k < heights.size(); ++k)
      weight_sum += ((k + 1 < heights.size() ? heights[k + 1] : heights[k]) -
                     (k > 0 ? heights[k - 1] : heights[k])) /
                    2.;
    EXPECT_EQ(closed.counts.n_open, 0u);
    EXPECT_DOUBLE_EQ(closed.closed_length, weight_sum);
    EXPECT_EQ(open.closed_length, 0.);
    EXPECT_EQ(open.mean_normal_stress, 0.);
  }

  TEST(JointReport, ClosedPairInTensionKeepsTheNodeMeasure)
  {
    // Intact tensile strength T: a pair with gap below T / kn = 1e-4 m is
    // closed in tension (phi = t_n / kn = -g < 0), so the indicator does not
    // change sign towards its open neighbour and the segment keeps the node
    // measure. Gap 1e-3 (y - 0.437): nodes up to 0.5 m closed (0.5 m:
    // 6.3e-5 m), 0.6 m open (1.63e-4 m); weights 0.05 + 5 x 0.1 = 0.55 m.
    const CoulombJoint<2> law = make_law(normal_stiffness, 1e6);
    const JointReport     report =
      report_of(uniform_heights(), law, [](const double height) {
        return std::make_pair(1e-3 * (height - 0.437), JointHistory<2>());
      });
    EXPECT_EQ(report.counts.n_open, 5u);
    EXPECT_NEAR(report.closed_length, 0.55, 1e-12);
  }

  /**
   * A vertical joint x = 0 (normal +x) of 5 straight nodes with a fillet
   * node at its top whose normal is tilted by 45 degrees: the joint forces
   * are the resultant's components along +x and the tangent (-n_y, n_x) =
   * +y, so the fillet node's traction counts with cos 45 deg in N and
   * with sin 45 deg in S.
   */
  TEST(JointReport, ForcesAreResultantComponentsAlongTheStraightPart)
  {
    std::vector<ContactNode<2>>   nodes;
    std::vector<JointResponse<2>> responses;
    constexpr double traction = 2e6; // Pa, compression at every node
    constexpr double spacing  = 0.1; // m
    for (unsigned int k = 0; k < 6; ++k)
      {
        ContactNode<2> node;
        node.position  = dealii::Point<2>(0., k * spacing);
        node.weight    = spacing;
        node.normal[0] = 1.;
        if (k == 5) // the fillet node
          {
            node.normal[0] = std::sqrt(0.5);
            node.normal[1] = std::sqrt(0.5);
          }
        nodes.push_back(node);
        JointResponse<2> response;
        response.state           = JointState::stick;
        response.normal_traction = traction;
        responses.push_back(response);
      }
    const JointReport report =
      make_joint_reports(nodes, responses, {"joint"}, 0.2).at(0);
    // Force density on side B: -t n. Along +x: -t (5 x 1 + cos 45) w, so
    // N = t w (5 + cos 45); along the tangent +y: -t sin 45 w for the
    // fillet node only. A scalar sum would give N = 6 t w, S = 0.
    const double w = spacing;
    EXPECT_NEAR(report.normal_force,
                traction * w * (5. + std::sqrt(0.5)),
                1e-9 * traction * w);
    EXPECT_NEAR(report.shear_force,
                -traction * w * std::sqrt(0.5),
                1e-9 * traction * w);
  }

  /** Weights larger than the node spacing (as on a fillet): the window
   *  mean must stay below the largest nodal traction. */
  TEST(JointReport, AveragedPeakNeverExceedsThePointwisePeak)
  {
    std::vector<ContactNode<2>>   nodes;
    std::vector<JointResponse<2>> responses;
    for (unsigned int k = 0; k < 8; ++k)
      {
        ContactNode<2> node;
        node.position  = dealii::Point<2>(0., 0.01 * k); // 1 cm apart
        node.weight    = 0.03;                           // 3 cm each
        node.normal[0] = 1.;
        nodes.push_back(node);
        JointResponse<2> response;
        response.state           = JointState::stick;
        response.normal_traction = 1e6 * (1. + k); // Pa, peak 8 MPa at k = 7
        responses.push_back(response);
      }
    const JointReport report =
      make_joint_reports(nodes, responses, {"joint"}, 0.05).at(0);
    EXPECT_DOUBLE_EQ(report.peak_normal_stress, 8e6);
    EXPECT_LE(report.averaged_peak_normal_stress, report.peak_normal_stress);
    // The last 5 cm hold node 7 (3 cm at 8 MPa) and 2 cm of node 6 (7 MPa).
    EXPECT_NEAR(report.averaged_peak_normal_stress,
                (0.03 * 8e6 + 0.02 * 7e6) / 0.05,
                1e-6);
  }

  TEST(LargestOverlap, IsTheMostNegativeGapOfAnyJoint)
  {
    JointReport first, second;
    for (const double gap : {1e-3, -2e-4, 0.})
      first.profile.push_back({0., {}, 0., 0., gap, JointState::stick});
    for (const double gap : {-5e-4, 3e-3})
      second.profile.push_back({0., {}, 0., 0., gap, JointState::slip});
    EXPECT_DOUBLE_EQ(largest_overlap({first, second}), 5e-4);
    // Open or touching joints do not overlap.
    EXPECT_DOUBLE_EQ(largest_overlap({JointReport{}}), 0.);
    second.profile = {{0., {}, 0., 0., 2e-3, JointState::open}};
    EXPECT_DOUBLE_EQ(largest_overlap({second}), 0.);
  }
} // namespace

// t_n = c sqrt(d) at distances 0.3 and 0.3 + 0.2 m from the end: the end
// lies 0.3 m beyond the last node, for any c; a negative traction at the
// end node counts as zero (the end is at the node).
TEST(SquareRootEdgeExtent, ExtrapolatesTheSquaredTractionToZero)
{
  const double c = 7.3e6;
  EXPECT_NEAR(FloorBlock::Postprocess::square_root_edge_extent(
                c * std::sqrt(0.3), c * std::sqrt(0.5), 0.2),
              0.3,
              1e-12);
  EXPECT_DOUBLE_EQ(
    FloorBlock::Postprocess::square_root_edge_extent(-1e3, 5e6, 0.2), 0.);
}
