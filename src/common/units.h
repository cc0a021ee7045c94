#pragma once

#include <cmath>

/**
 * Unit conversions at the edges of the program. Everything inside FloorBlock
 * is SI (m, N, Pa, kg, s, rad); these helpers are used only where a value
 * enters from a parameter file or leaves for a human-readable table.
 */
namespace FloorBlock::Units
{
  /// Standard gravity (m/s^2): defines the tonne-force, independent of the
  /// scene's own gravity parameter.
  constexpr double standard_gravity = 9.80665;

  constexpr double pi = 3.14159265358979323846;

  constexpr double
  degrees_to_radians(const double degrees)
  {
    return degrees * pi / 180.0;
  }

  constexpr double
  radians_to_degrees(const double radians)
  {
    return radians * 180.0 / pi;
  }

  /// Tonnes-force (the mining convention for support loads) to newtons.
  constexpr double
  tonnes_force_to_newtons(const double tonnes)
  {
    return tonnes * 1000.0 * standard_gravity;
  }

  constexpr double newtons_per_kilonewton = 1.0e3;
  constexpr double pascals_per_megapascal = 1.0e6;

  /** Short names for output in kN and MPa: a value in N divided by kN. */
  constexpr double kN  = newtons_per_kilonewton;
  constexpr double MPa = pascals_per_megapascal;
} // namespace FloorBlock::Units
