// The tool shall give the Hertz half-width and peak pressure of a cylinder
// on a flat (Johnson 1985, eqs. 4.43 and 4.45).

#include <analytic/hertz.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>

using namespace FloorBlock::Analytic;

namespace
{
  // Hand example: steel roller on a rigid flat, E = 200 GPa, nu = 0.3,
  // R = 50 mm, P = 100 kN/m.
  // E* = E / (1 - nu^2) = 200e9 / 0.91 = 219.7802 GPa;
  // pi E* = 690.4599 GPa; 4 P R = 4 * 1e5 * 0.05 = 2e4 N;
  // a^2 = 2e4 / 690.4599e9 = 2.896620e-8 m^2, a = 0.1701946 mm;
  // p0 = 2 P / (pi a) = 2e5 / 5.346821e-4 = 374.0541 MPa.
  constexpr double youngs_modulus = 200e9, poissons_ratio = 0.3;
  constexpr double radius = 0.05, line_load = 1e5;
  constexpr double hand_tolerance = 1e-6; // hand values carry 7 digits

  double
  contact_modulus()
  {
    return youngs_modulus / (1. - poissons_ratio * poissons_ratio);
  }
} // namespace

TEST(Hertz, ShallReproduceTheHandComputedExample)
{
  const HertzLineContact contact =
    hertz_line_contact(line_load, radius, contact_modulus());
  EXPECT_EQ(contact.status, Status::ok);
  EXPECT_NEAR(contact.half_width * 1e3 / 0.1701946, 1., hand_tolerance);
  EXPECT_NEAR(contact.peak_pressure / 374.0541e6, 1., hand_tolerance);
}

TEST(Hertz, ShallCarryTheLineLoadWithItsEllipticPressure)
{
  // The elliptic pressure integrates to pi a p0 / 2, which must be P.
  const HertzLineContact contact =
    hertz_line_contact(line_load, radius, contact_modulus());
  EXPECT_NEAR(M_PI * contact.half_width * contact.peak_pressure / 2.,
              line_load,
              1e-12 * line_load);
  // a grows as sqrt(P R / E*): four times the load doubles the width.
  const HertzLineContact loaded =
    hertz_line_contact(4. * line_load, radius, contact_modulus());
  EXPECT_NEAR(loaded.half_width,
              2. * contact.half_width,
              1e-12 * contact.half_width);
}

TEST(Hertz, ShallReportInvalidInputInsteadOfInfOrNaN)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto &[load, size, modulus] :
       {std::make_tuple(0., radius, contact_modulus()),
        std::make_tuple(line_load, -radius, contact_modulus()),
        std::make_tuple(line_load, radius, 0.),
        std::make_tuple(nan, radius, contact_modulus()),
        std::make_tuple(1e300, 1e300, 1e-300)})
    {
      const HertzLineContact contact = hertz_line_contact(load, size, modulus);
      EXPECT_EQ(contact.status, Status::invalid_input);
      EXPECT_EQ(contact.half_width, 0.);
      EXPECT_EQ(contact.peak_pressure, 0.);
    }
}

// Eq. 4.75 on the axis: both stresses -p0 at the surface, and the largest
// shear (sigma_x - sigma_z)/2 = 0.30 p0 at z = 0.78 a (Johnson 1985, p. 101).
TEST(HertzAxisStress, SurfaceValueAndLargestShear)
{
  const double p0 = 1e6, a = 0.02;
  const auto   surface = hertz_axis_stress(p0, a, 0.);
  EXPECT_NEAR(surface.along_surface, -p0, 1e-9);
  EXPECT_NEAR(surface.into_body, -p0, 1e-9);
  double largest = 0., where = 0.;
  for (double z = 0.; z <= 2. * a; z += 1e-4 * a)
    {
      const auto   stress = hertz_axis_stress(p0, a, z);
      const double shear  = 0.5 * (stress.along_surface - stress.into_body);
      if (shear > largest)
        {
          largest = shear;
          where   = z;
        }
    }
  EXPECT_NEAR(largest / p0, 0.30, 0.005);
  EXPECT_NEAR(where / a, 0.78, 0.01); // 0.786 a to three digits
}
