// The tool shall derive block inclinations, floor lift and elastic moduli.

#include <analytic/floor_shape.h>
#include <common/input_error.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace FloorBlock;
using namespace FloorBlock::Analytic;

TEST(FloorShape, ShallGiveEachBlockTheChordSlopeOfTheParabola)
{
  const double              width = 1., curvature = 200.;
  const std::size_t         n_blocks = 6;
  const std::vector<double> inclinations =
    parabolic_inclinations(n_blocks, width, curvature);
  ASSERT_EQ(inclinations.size(), n_blocks);
  for (std::size_t block = 0; block < n_blocks; ++block)
    {
      // Block index 0 is farthest: it spans x from (n-1) L to n L.
      const double near_edge = (n_blocks - 1 - block) * width;
      const double far_edge  = near_edge + width;
      const double chord_slope =
        (far_edge * far_edge - near_edge * near_edge) / curvature / width;
      EXPECT_NEAR(std::tan(inclinations[block]), chord_slope, 1e-15);
    }
}

TEST(FloorShape, ShallGiveTheFloorElevationAtXEqualLAsLiftAtTheFace)
{
  const double              width = 1., curvature = 400.;
  const std::vector<double> inclinations =
    parabolic_inclinations(3, width, curvature);
  EXPECT_NEAR(joint_floor_lift(inclinations.back(), 0., width),
              width * width / curvature,
              1e-15);
  EXPECT_LT(joint_floor_lift(0., 0.01, width), 0.);
}

// The FEM lifts a flat bed to the height the closed forms' block
// inclinations reach at the free end: the sum of L tan(alpha_i).
TEST(FloorShape, ShallRiseAsTheClosedFormsInclinationsAtTheFreeEnd)
{
  const double      width = 1.2, curvature = 100.;
  const std::size_t n_blocks  = 8;
  double            chord_sum = 0.;
  for (const double alpha : parabolic_inclinations(n_blocks, width, curvature))
    chord_sum += width * std::tan(alpha);
  const double rise = parabolic_bedding_rise(n_blocks, width, curvature);
  EXPECT_NEAR(rise, chord_sum, 1e-14);
  EXPECT_NEAR(rise, 0.9216, 1e-15); // (8 x 1.2 m)^2 / 100 m
  EXPECT_NEAR(planar_bedding_rise(6, 1., std::atan(0.02)), 0.12, 1e-15);
  EXPECT_LT(planar_bedding_rise(6, 1., -0.1), 0.);
  EXPECT_THROW(parabolic_bedding_rise(0, 1., 100.), InputError);
  EXPECT_THROW(planar_bedding_rise(3, 1., M_PI_2), InputError);
}

TEST(FloorShape, ShallConvertBulkAndShearModulusConsistently)
{
  const double bulk = 9.e9, shear = 6.7e9;
  const double youngs  = youngs_modulus_from_bulk_shear(bulk, shear);
  const double poisson = poisson_ratio_from_bulk_shear(bulk, shear);
  // Independent identities of isotropic elasticity.
  EXPECT_NEAR(youngs / (2. * shear * (1. + poisson)), 1., 1e-14);
  EXPECT_NEAR(youngs / (3. * bulk * (1. - 2. * poisson)), 1., 1e-14);
  EXPECT_NEAR(youngs / 1e9, 16.10386, 1e-5); // 9*9*6.7/33.7 by hand
}

TEST(FloorShape, ShallRejectNonPositiveSizesAsInputErrors)
{
  EXPECT_THROW(parabolic_inclinations(0, 1., 100.), InputError);
  EXPECT_THROW(parabolic_inclinations(3, 1., 0.), InputError);
  EXPECT_THROW(youngs_modulus_from_bulk_shear(-1., 1.), InputError);
  EXPECT_THROW(joint_floor_lift(std::nan(""), 0., 1.), InputError);
  EXPECT_THROW(joint_floor_lift(0.1, 0., 0.), InputError);
}
