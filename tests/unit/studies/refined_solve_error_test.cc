// The two-grid estimates of one pair of solves (studies/error_estimate):
// Roache's GCI for the coarse solve (6 times the difference) and for the
// refined one (3 times), each plus its own contact ends' uncertainty; and
// their guard against a level and its check agreeing by chance.

#include <gtest/gtest.h>
#include <studies/error_estimate.h>

using namespace FloorBlock;
using Output::ReportedSolve;

namespace
{
  /** A converged solve whose last increment has one joint, the face's. */
  Pipeline::FemOutcome
  solve_with_face(const double contact_length,
                  const double ends_uncertainty,
                  const double normal_force)
  {
    Contact::JointReport face;
    face.name                      = "vertical 6";
    face.normal_force              = normal_force;
    face.closed_length             = contact_length;
    face.closed_length_uncertainty = ends_uncertainty;
    Contact::IncrementResult increment;
    increment.joints = {face};
    Pipeline::FemOutcome outcome;
    outcome.converged         = true;
    outcome.result.increments = {increment};
    return outcome;
  }

  // The exact law's default scene: level 4 and its check.
  const Pipeline::FemOutcome coarse = solve_with_face(0.0978575, 7e-5, 2.7e6);
  const Pipeline::FemOutcome fine   = solve_with_face(0.0981692, 2e-5, 2.701e6);
} // namespace

// The tool shall estimate the coarse solve's error as 6 times the
// difference plus the coarse solve's ends' uncertainty, and report the
// coarse value; the refined solve's value is kept beside it.
TEST(RefinedSolveError, CoarseSolveGetsSixTimesTheDifference)
{
  const auto estimate = Studies::refined_solve_error(coarse, fine);
  ASSERT_TRUE(estimate.available);
  EXPECT_EQ(estimate.reported_solve, ReportedSolve::coarse);
  const auto &length = estimate.joints.at("vertical 6").contact_length;
  EXPECT_DOUBLE_EQ(length.value, 0.0978575);
  EXPECT_DOUBLE_EQ(length.coarse_value, 0.0978575);
  EXPECT_DOUBLE_EQ(length.refined_value, 0.0981692);
  EXPECT_NEAR(length.absolute_error, 6. * 3.117e-4 + 7e-5, 1e-12);
  EXPECT_NEAR(*length.relative_error, length.absolute_error / 0.0981692, 1e-15);
  const auto &force = estimate.joints.at("vertical 6").normal_force;
  EXPECT_NEAR(force.absolute_error, 6. * 1e3, 1e-6); // no ends' term
}

// The tool shall estimate the refined solve's error as 3 times the same
// difference plus the refined solve's own ends' uncertainty, and then
// report the refined value.
TEST(RefinedSolveError, RefinedSolveGetsThreeTimesTheDifference)
{
  const auto estimate =
    Studies::refined_solve_error(coarse, fine, ReportedSolve::refined);
  ASSERT_TRUE(estimate.available);
  EXPECT_EQ(estimate.reported_solve, ReportedSolve::refined);
  EXPECT_NE(estimate.method.find("refined solve"), std::string::npos)
    << estimate.method;
  const auto &length = estimate.joints.at("vertical 6").contact_length;
  EXPECT_DOUBLE_EQ(length.value, 0.0981692);
  EXPECT_DOUBLE_EQ(length.coarse_value, 0.0978575);
  EXPECT_NEAR(length.absolute_error, 3. * 3.117e-4 + 2e-5, 1e-12);
  const auto &force = estimate.joints.at("vertical 6").normal_force;
  EXPECT_DOUBLE_EQ(force.value, 2.701e6);
  EXPECT_NEAR(force.absolute_error, 3. * 1e3, 1e-6);
}

// A refined solve that did not converge describes another load state: no
// estimate for either solve, with the reason.
TEST(RefinedSolveError, UnconvergedRefinedSolveGivesNoEstimate)
{
  auto failed               = fine;
  failed.converged          = false;
  failed.report.status_text = "stopped after 4 cutbacks";
  for (const ReportedSolve reported :
       {ReportedSolve::coarse, ReportedSolve::refined})
    {
      const auto estimate =
        Studies::refined_solve_error(coarse, failed, reported);
      EXPECT_FALSE(estimate.available);
      EXPECT_NE(estimate.status_text.find("stopped after 4 cutbacks"),
                std::string::npos);
    }
}

// The exact law at vertical friction 60 deg: levels 2 and 3
// and level 3's check gave 190.54, 190.37 and 190.38 mm. The check moved
// the length opposite to the step from level 2, so the pair's agreement is
// no evidence: the tool shall widen both estimates to the range of the
// three values, mark the figure and say so in the method.
TEST(WidenWhereOscillating, ReversedCheckGetsTheRangeOfThreeValues)
{
  const auto level_2 = solve_with_face(0.19054, 1e-5, 2.6720e6);
  const auto level_3 = solve_with_face(0.19037, 1.8e-5, 2.6721e6);
  const auto check   = solve_with_face(0.19038, 1e-5, 2.6722e6);
  for (const ReportedSolve reported :
       {ReportedSolve::coarse, ReportedSolve::refined})
    {
      auto estimate = Studies::refined_solve_error(level_3, check, reported);
      const double pair_error =
        estimate.joints.at("vertical 6").contact_length.absolute_error;
      ASSERT_LT(pair_error, 1e-4);
      Studies::widen_where_oscillating(estimate, level_2);
      const auto &length = estimate.joints.at("vertical 6").contact_length;
      EXPECT_TRUE(length.oscillating);
      EXPECT_NEAR(length.absolute_error, 0.19054 - 0.19037, 1e-12);
      EXPECT_NEAR(*length.relative_error,
                  length.absolute_error / 0.19038,
                  1e-15);
      EXPECT_NE(estimate.method.find("range of the three values"),
                std::string::npos);
      // Q rose on both steps: monotone, its pair estimate stays.
      const auto &force = estimate.joints.at("vertical 6").normal_force;
      EXPECT_FALSE(force.oscillating);
      EXPECT_NEAR(force.absolute_error,
                  Studies::error_per_difference(reported) * 100.,
                  1e-6);
    }
}

// A check that continues the previous step's direction (the exact law at
// 30 deg: 97.78, 97.86, then 98.17 mm) leaves the estimate as it was; so
// does a range smaller than the pair's estimate, which is marked but not
// widened, and the method then says nothing of it.
TEST(WidenWhereOscillating, MonotoneOrNarrowRangeLeavesTheEstimate)
{
  const auto monotone = Studies::refined_solve_error(coarse, fine);
  auto       widened  = monotone;
  Studies::widen_where_oscillating(widened,
                                   solve_with_face(0.09778, 7e-5, 2.6999e6));
  const auto &length = widened.joints.at("vertical 6").contact_length;
  EXPECT_FALSE(length.oscillating);
  EXPECT_EQ(length.absolute_error,
            monotone.joints.at("vertical 6").contact_length.absolute_error);
  EXPECT_EQ(widened.method, monotone.method);

  auto narrow = monotone;
  Studies::widen_where_oscillating(narrow,
                                   solve_with_face(0.09790, 7e-5, 2.7e6));
  EXPECT_TRUE(narrow.joints.at("vertical 6").contact_length.oscillating);
  EXPECT_EQ(narrow.joints.at("vertical 6").contact_length.absolute_error,
            monotone.joints.at("vertical 6").contact_length.absolute_error);
  EXPECT_EQ(narrow.method, monotone.method);
}

// The tool shall widen an estimate whose next adaptive level lies outside
// its bracket to the distance to that level (the exact law with FE degree
// 2 on the default scene: level 0 97.468 mm, its check 97.499
// mm, level 1 98.04 mm; converged 98.42 mm), and record the level's value.
TEST(WidenToContain, NextLevelOutsideTheBracketWidensIt)
{
  const auto level_0 = solve_with_face(0.097468, 2e-4, 2.7167e6);
  const auto check   = solve_with_face(0.097499, 2e-4, 2.7170e6);
  const auto level_1 = solve_with_face(0.09804, 2e-4, 2.7171e6);
  auto       estimate =
    Studies::refined_solve_error(level_0, check, ReportedSolve::refined);
  const double before =
    estimate.joints.at("vertical 6").contact_length.absolute_error;
  ASSERT_NEAR(before, 3. * 3.1e-5 + 2e-4, 1e-12); // 0.30 %: misses 98.42
  Studies::widen_to_contain(estimate, level_1, 1);
  const auto &length = estimate.joints.at("vertical 6").contact_length;
  EXPECT_NEAR(length.absolute_error, 0.09804 - 0.097499, 1e-12);
  EXPECT_NEAR(*length.relative_error, (0.09804 - 0.097499) / 0.097499, 1e-12);
  ASSERT_TRUE(length.next_level_value.has_value());
  EXPECT_DOUBLE_EQ(*length.next_level_value, 0.09804);
  // The force's level 1 lies inside its bracket (3 x 300 N): unchanged.
  const auto &force = estimate.joints.at("vertical 6").normal_force;
  EXPECT_NEAR(force.absolute_error, 3. * 300., 1e-6);
  EXPECT_NE(estimate.method.find("level 1 lies outside"), std::string::npos);
}

// The tool shall leave an estimate whose next level lies inside every
// bracket as it is (the default compliant scene: level 0
// 347.07 mm +- 1.18 mm, level 1 347.20 mm).
TEST(WidenToContain, NextLevelInsideLeavesTheEstimate)
{
  const auto level_0  = solve_with_face(0.3470692, 5e-5, 2726259.);
  const auto check    = solve_with_face(0.3472152, 5e-5, 2727968.);
  const auto level_1  = solve_with_face(0.3472025, 5e-5, 2727540.);
  auto       estimate = Studies::refined_solve_error(level_0, check);
  const auto before   = estimate.joints.at("vertical 6");
  Studies::widen_to_contain(estimate, level_1, 1);
  const auto &after = estimate.joints.at("vertical 6");
  EXPECT_DOUBLE_EQ(after.contact_length.absolute_error,
                   before.contact_length.absolute_error);
  EXPECT_DOUBLE_EQ(after.normal_force.absolute_error,
                   before.normal_force.absolute_error);
  EXPECT_DOUBLE_EQ(*after.contact_length.next_level_value, 0.3472025);
  EXPECT_EQ(estimate.method.find("outside"), std::string::npos);
}

namespace
{
  /** A resolved corner (cells of L/8) with the given factors. */
  Safety::CornerSafety
  corner(const double point_factor, const double line_factor)
  {
    Safety::CornerSafety result;
    result.path.block        = "face block";
    result.path.joint_name   = "vertical 6";
    result.critical_distance = 0.02;
    result.largest_cell      = 0.02 / 8.;
    result.point_factor      = point_factor;
    result.line_factor       = line_factor;
    return result;
  }
} // namespace

// The tool shall estimate the corners' safety factors like the joints'
// figures: 6 times the difference for the coarse solve, 3 times for the
// refined one, by corner label.
TEST(RefinedSolveError, CornerFactorsGetTheSameFactorPerDifference)
{
  auto with_corner    = coarse;
  auto fine_corner    = fine;
  with_corner.report.corner_safety = {corner(0.535, 0.673)};
  fine_corner.report.corner_safety = {corner(0.525, 0.674)};
  const auto estimate = Studies::refined_solve_error(with_corner, fine_corner);
  const auto &point   = estimate.corners.at("face block at vertical 6").point_factor;
  EXPECT_DOUBLE_EQ(point.value, 0.535);
  EXPECT_NEAR(point.absolute_error, 6. * 0.010, 1e-12);
  EXPECT_NEAR(*point.relative_error, 6. * 0.010 / 0.525, 1e-12);
  const auto refined = Studies::refined_solve_error(
    with_corner, fine_corner, ReportedSolve::refined);
  const auto &line = refined.corners.at("face block at vertical 6").line_factor;
  EXPECT_DOUBLE_EQ(line.value, 0.674);
  EXPECT_NEAR(line.absolute_error, 3. * 0.001, 1e-12);
}

// A corner that either solve does not resolve has a cell's value, not a
// figure: no estimate for it.
TEST(RefinedSolveError, UnresolvedCornerGetsNoEstimate)
{
  auto with_corner = coarse;
  auto fine_corner = fine;
  with_corner.report.corner_safety = {corner(0.535, 0.673)};
  fine_corner.report.corner_safety = {corner(0.525, 0.674)};
  fine_corner.report.corner_safety.front().largest_cell = 0.02 / 2.;
  const auto estimate = Studies::refined_solve_error(with_corner, fine_corner);
  EXPECT_TRUE(estimate.corners.empty());
}

// A confirming level outside a corner factor's bracket widens it to the
// distance, as for the joints' figures.
TEST(RefinedSolveError, NextLevelOutsideTheBracketWidensACornerFactor)
{
  auto with_corner = coarse;
  auto fine_corner = fine;
  with_corner.report.corner_safety = {corner(0.535, 0.673)};
  fine_corner.report.corner_safety = {corner(0.534, 0.673)};
  auto estimate = Studies::refined_solve_error(with_corner, fine_corner);
  auto next     = fine_corner;
  next.report.corner_safety = {corner(0.500, 0.673)};
  Studies::widen_to_contain(estimate, next, 1);
  const auto &point = estimate.corners.at("face block at vertical 6").point_factor;
  EXPECT_NEAR(point.absolute_error, 0.035, 1e-12);
  EXPECT_DOUBLE_EQ(*point.next_level_value, 0.500);
}
