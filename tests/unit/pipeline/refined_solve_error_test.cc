// The two-grid estimates of one pair of solves (pipeline/error_estimate):
// Roache's GCI for the coarse solve (6 times the difference) and for the
// refined one (3 times), each plus its own contact ends' uncertainty.

#include <pipeline/error_estimate.h>

#include <gtest/gtest.h>

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
    outcome.converged = true;
    outcome.result.increments = {increment};
    return outcome;
  }

  // The exact law's default scene, session 21: level 4 and its check.
  const Pipeline::FemOutcome coarse = solve_with_face(0.0978575, 7e-5, 2.7e6);
  const Pipeline::FemOutcome fine   = solve_with_face(0.0981692, 2e-5, 2.701e6);
} // namespace

// The tool shall estimate the coarse solve's error as 6 times the
// difference plus the coarse solve's ends' uncertainty, and report the
// coarse value; the refined solve's value is kept beside it.
TEST(RefinedSolveError, CoarseSolveGetsSixTimesTheDifference)
{
  const auto estimate = Pipeline::refined_solve_error(coarse, fine);
  ASSERT_TRUE(estimate.available);
  EXPECT_EQ(estimate.reported_solve, ReportedSolve::coarse);
  const auto &length = estimate.joints.at("vertical 6").contact_length;
  EXPECT_DOUBLE_EQ(length.value, 0.0978575);
  EXPECT_DOUBLE_EQ(length.coarse_value, 0.0978575);
  EXPECT_DOUBLE_EQ(length.refined_value, 0.0981692);
  EXPECT_NEAR(length.absolute_error, 6. * 3.117e-4 + 7e-5, 1e-12);
  EXPECT_NEAR(*length.relative_error, length.absolute_error / 0.0981692,
              1e-15);
  const auto &force = estimate.joints.at("vertical 6").normal_force;
  EXPECT_NEAR(force.absolute_error, 6. * 1e3, 1e-6); // no ends' term
}

// The tool shall estimate the refined solve's error as 3 times the same
// difference plus the refined solve's own ends' uncertainty, and then
// report the refined value.
TEST(RefinedSolveError, RefinedSolveGetsThreeTimesTheDifference)
{
  const auto estimate =
    Pipeline::refined_solve_error(coarse, fine, ReportedSolve::refined);
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
  auto failed        = fine;
  failed.converged   = false;
  failed.report.status_text = "stopped after 4 cutbacks";
  for (const ReportedSolve reported :
       {ReportedSolve::coarse, ReportedSolve::refined})
    {
      const auto estimate =
        Pipeline::refined_solve_error(coarse, failed, reported);
      EXPECT_FALSE(estimate.available);
      EXPECT_NE(estimate.status_text.find("stopped after 4 cutbacks"),
                std::string::npos);
    }
}
