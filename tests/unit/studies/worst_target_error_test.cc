#include <gtest/gtest.h>
#include <studies/accuracy_loop.h>

#include <cmath>

using namespace FloorBlock;
using Parameters::TargetFigure;

namespace
{
  Output::FemErrorEstimate
  estimate_of_face(const Output::JointErrors &errors)
  {
    Output::FemErrorEstimate estimate;
    estimate.available            = true;
    estimate.joints["vertical 6"] = errors;
    return estimate;
  }

  /** value, refined value, absolute and relative error; the rest default. */
  Output::FigureError
  figure_error(const double                value,
               const double                refined_value,
               const double                absolute_error,
               const std::optional<double> relative_error)
  {
    Output::FigureError error;
    error.value          = value;
    error.refined_value  = refined_value;
    error.absolute_error = absolute_error;
    error.relative_error = relative_error;
    return error;
  }

  Output::JointErrors
  face_errors()
  {
    Output::JointErrors errors;
    errors.normal_force       = figure_error(1e6, 1.001e6, 6e3, 0.006);
    errors.contact_length     = figure_error(0.3, 0.301, 0.006, 0.02);
    errors.sigma_max          = figure_error(1e7, 1.1e7, 6e6, 0.55);
    errors.sigma_max_averaged = figure_error(1e7, 1.01e7, 6e5, 0.06);
    return errors;
  }
} // namespace

// The loop stops on the largest relative error among the target figures
// only: the peaks' errors do not count unless they are targets.
TEST(WorstTargetError, IsTheLargestAmongTheTargetFiguresOnly)
{
  const auto estimate = estimate_of_face(face_errors());
  EXPECT_DOUBLE_EQ(*Studies::worst_target_error(estimate,
                                                "vertical 6",
                                                {TargetFigure::normal_force,
                                                 TargetFigure::contact_length}),
                   0.02);
  EXPECT_DOUBLE_EQ(*Studies::worst_target_error(estimate,
                                                "vertical 6",
                                                {TargetFigure::normal_force}),
                   0.006);
  EXPECT_DOUBLE_EQ(*Studies::worst_target_error(estimate,
                                                "vertical 6",
                                                {TargetFigure::normal_force,
                                                 TargetFigure::sigma_max}),
                   0.55);
  EXPECT_DOUBLE_EQ(
    *Studies::worst_target_error(estimate,
                                 "vertical 6",
                                 {TargetFigure::sigma_max_averaged}),
    0.06);
}

// An open joint on both levels (0 and 0) meets any target; a figure that
// is 0 on the refined level but not on the coarse one has no relative
// error and must not count as met.
TEST(WorstTargetError, ZeroRefinedValueCountsOnlyIfBothLevelsAgree)
{
  auto errors           = face_errors();
  errors.contact_length = figure_error(0., 0., 0., std::nullopt);
  EXPECT_DOUBLE_EQ(*Studies::worst_target_error(estimate_of_face(errors),
                                                "vertical 6",
                                                {TargetFigure::contact_length}),
                   0.);
  errors.contact_length = figure_error(0.01, 0., 0.06, std::nullopt);
  EXPECT_TRUE(std::isinf(*Studies::worst_target_error(
    estimate_of_face(errors), "vertical 6", {TargetFigure::contact_length})));
}

TEST(WorstTargetError, NoneWithoutAnEstimateOfTheJoint)
{
  auto estimate = estimate_of_face(face_errors());
  EXPECT_FALSE(Studies::worst_target_error(estimate,
                                           "vertical 3",
                                           {TargetFigure::normal_force}));
  estimate.available = false;
  EXPECT_FALSE(Studies::worst_target_error(estimate,
                                           "vertical 6",
                                           {TargetFigure::normal_force}));
}

TEST(TargetFigureKey, NamesTheFemJsonKeys)
{
  EXPECT_EQ(Studies::target_figure_key(TargetFigure::normal_force),
            "normal_force_N_per_m");
  EXPECT_EQ(Studies::target_figure_key(TargetFigure::contact_length),
            "contact_length_m");
  EXPECT_EQ(Studies::target_figure_key(TargetFigure::sigma_max),
            "sigma_max_Pa");
  EXPECT_EQ(Studies::target_figure_key(TargetFigure::sigma_max_averaged),
            "sigma_max_averaged_Pa");
}
