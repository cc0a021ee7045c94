// The theory of critical distances: L from K_Ic and sigma_t, the point
// and line methods on the Hertz line contact's axis, whose stresses are
// known in closed form (Johnson 1985, eq. 4.75), and the area method on
// fields whose means over a quarter disc are known in closed form.

#include <analytic/hertz.h>
#include <strength/critical_distance.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace FloorBlock;

TEST(CriticalDistance, FromToughnessAndTensileStrength)
{
  // K_Ic = 1 MPa m^0.5, sigma_t = 4 MPa: L = (1/pi)(0.25)^2 m = 19.9 mm.
  EXPECT_NEAR(Strength::critical_distance(1e6, 4e6), 0.0625 / M_PI, 1e-15);
}

namespace
{
  constexpr double p0 = 30e6; // Pa
  constexpr double a  = 0.01; // m

  /** The Hertz axis sampled every @p spacing from the surface to @p depth. */
  std::vector<Strength::PathSample>
  hertz_axis(const double depth, const double spacing)
  {
    std::vector<Strength::PathSample> path;
    const auto n = static_cast<unsigned int>(std::ceil(depth / spacing));
    for (unsigned int k = 0; k <= n; ++k)
      {
        const double z      = std::min(k * spacing, depth);
        const auto   stress = Analytic::hertz_axis_stress(p0, a, z);
        path.push_back({z, {stress.along_surface, stress.into_body, 0., 0.}});
      }
    return path;
  }
} // namespace

// Point method at L/2 = a and 2a: within 1 % of the closed form from
// samples a/10 apart (linear interpolation between them).
TEST(CriticalDistance, PointMethodOnTheHertzAxis)
{
  const auto path = hertz_axis(5. * a, 0.1 * a);
  for (const double length : {2. * a, 4. * a, 2.3 * a})
    {
      const auto exact    = Analytic::hertz_axis_stress(p0, a, 0.5 * length);
      const auto computed = Strength::point_method_stress(path, length);
      EXPECT_NEAR(computed.xx / exact.along_surface, 1., 0.01) << length;
      EXPECT_NEAR(computed.yy / exact.into_body, 1., 0.01) << length;
    }
}

// Line method over L = a and 2a against the integrals of eq. 4.75:
// mean sigma_z = -p0 (a/L) asinh(L/a), mean sigma_x = -(p0/a)(sqrt(a^2 +
// L^2) - L) (the antiderivative of (a^2 + 2z^2)/sqrt(a^2 + z^2) is
// z sqrt(a^2 + z^2)).
TEST(CriticalDistance, LineMethodOnTheHertzAxis)
{
  const auto path = hertz_axis(3. * a, 0.1 * a);
  for (const double length : {a, 2. * a})
    {
      const double mean_z = -p0 * a / length * std::asinh(length / a);
      const double mean_x =
        -p0 / a * (std::sqrt(a * a + length * length) - length);
      const auto computed = Strength::line_method_stress(path, length);
      EXPECT_NEAR(computed.xx / mean_x, 1., 0.01) << length;
      EXPECT_NEAR(computed.yy / mean_z, 1., 0.01) << length;
    }
}

// Exact for a field linear between the samples, with L between samples.
TEST(CriticalDistance, ExactForALinearField)
{
  std::vector<Strength::PathSample> path;
  for (const double d : {0., 0.003, 0.01, 0.04})
    path.push_back({d, {1e6 + 2e8 * d, 0., 0., 0.}});
  EXPECT_NEAR(Strength::line_method_stress(path, 0.02).xx, 1e6 + 2e8 * 0.01, 1e-6);
  EXPECT_NEAR(Strength::point_method_stress(path, 0.02).xx, 1e6 + 2e8 * 0.01, 1e-6);
}

TEST(CriticalDistance, RefusesAPathThatDoesNotReachL)
{
  const auto path = hertz_axis(a, 0.1 * a);
  EXPECT_THROW(Strength::line_method_stress(path, 2. * a), std::invalid_argument);
  EXPECT_NO_THROW(Strength::point_method_stress(path, 2. * a));
  EXPECT_THROW(Strength::point_method_stress(path, 3. * a), std::invalid_argument);
}

namespace
{
  /** Rays over the quarter disc 0 <= theta <= pi/2, radius @p length, of
   * the field sigma_xx = x^2, sigma_yy = 6 x, sigma_xy = x y. */
  std::vector<std::vector<Strength::PathSample>>
  quarter_disc_rays(const double length, const unsigned int n_rays)
  {
    std::vector<std::vector<Strength::PathSample>> rays;
    for (unsigned int j = 0; j < n_rays; ++j)
      {
        const double theta = 0.5 * M_PI * (j + 0.5) / n_rays;
        std::vector<Strength::PathSample> ray;
        for (unsigned int k = 0; k <= 128; ++k)
          {
            const double rho = 1.1 * length * k / 128;
            const double x   = rho * std::cos(theta);
            const double y   = rho * std::sin(theta);
            ray.push_back({rho, {x * x, 6. * x, x * y, 0.}});
          }
        rays.push_back(ray);
      }
    return rays;
  }
} // namespace

// Area method over a quarter disc of radius L, sampled on 16 rays as the
// corners are: mean x^2 = L^2/4, mean x = 4L/(3 pi), mean x y =
// L^2/(2 pi), within 0.5 % (the midpoint rule in angle).
TEST(CriticalDistance, AreaMethodOverAQuarterDisc)
{
  const double length = 0.02;
  const auto   mean   = Strength::area_method_stress(quarter_disc_rays(length, 16), length);
  EXPECT_NEAR(mean.xx / (0.25 * length * length), 1., 0.005);
  EXPECT_NEAR(mean.yy / (8. * length / M_PI), 1., 0.005);
  EXPECT_NEAR(mean.xy / (length * length / (2. * M_PI)), 1., 0.005);
}

// A field uniform in angle and linear in the radius, a + b rho: its
// mean over the disc is a + (2/3) b L, exactly, with L between samples.
TEST(CriticalDistance, AreaMethodExactForARadiallyLinearField)
{
  std::vector<Strength::PathSample> ray;
  for (const double d : {0., 0.003, 0.01, 0.04})
    ray.push_back({d, {1e6 + 2e8 * d, 0., 0., 0.}});
  const auto mean = Strength::area_method_stress({ray, ray, ray}, 0.02);
  EXPECT_NEAR(mean.xx, 1e6 + 2e8 * 2. / 3. * 0.02, 1e-6);
  EXPECT_THROW(Strength::area_method_stress({}, 0.02), std::invalid_argument);
  EXPECT_THROW(Strength::area_method_stress({ray}, 0.05), std::invalid_argument);
}
