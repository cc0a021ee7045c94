#include <common/units.h>
#include <strength/barton_bandis.h>

#include <cmath>

namespace FloorBlock::Strength
{
  namespace
  {
    // The relations are fitted in MPa, mm and degrees. Inputs are converted
    // to those units on entry and results back to SI on return, here only.
    constexpr double millimetres_per_metre = 1.0e3;
    constexpr double megapascals_per_pascal = 1.0 / Units::MPa;
    /// 1 MPa/mm = 1e6 Pa / 1e-3 m.
    constexpr double pascals_per_metre_per_megapascal_per_millimetre = 1.0e9;

    /** JCS/a_j in MPa/mm, the argument of both Bandis fits. */
    double
    wall_strength_over_aperture(const BartonBandisJoint &joint)
    {
      return (joint.wall_strength * megapascals_per_pascal) /
             (joint.initial_aperture * millimetres_per_metre);
    }
  } // namespace

  double
  barton_initial_aperture(const double roughness_coefficient,
                          const double wall_strength,
                          const double intact_ucs)
  {
    // Barton, Bandis and Bakhtar (1985); mm, a ratio of strengths.
    constexpr double roughness_divisor = 5.;
    constexpr double strength_factor   = 0.2;
    constexpr double offset            = 0.1;
    const double     aperture_mm =
      roughness_coefficient / roughness_divisor *
      (strength_factor * intact_ucs / wall_strength - offset);
    return aperture_mm / millimetres_per_metre;
  }

  double
  bandis_initial_normal_stiffness(const BartonBandisJoint &joint)
  {
    // Bandis, Lumsden and Barton (1983), fresh joints, first cycle, MPa/mm.
    constexpr double intercept       = -7.15;
    constexpr double per_roughness   = 1.75;
    constexpr double per_strength_mm = 0.02;
    const double     stiffness_mpa_per_mm =
      intercept + per_roughness * joint.roughness_coefficient +
      per_strength_mm * wall_strength_over_aperture(joint);
    return stiffness_mpa_per_mm *
           pascals_per_metre_per_megapascal_per_millimetre;
  }

  double
  bandis_maximum_closure(const BartonBandisJoint &joint)
  {
    // Bandis, Lumsden and Barton (1983), fresh joints, first cycle, mm.
    // A, B, C, D as published; the third cycle's (-0.1032, -0.0074, 1.1350,
    // -0.2510) give a smaller closure of a joint already closed twice.
    constexpr double A = -0.2960;
    constexpr double B = -0.0056;
    constexpr double C = 2.2410;
    constexpr double D = -0.2450;
    const double     closure_mm =
      A + B * joint.roughness_coefficient +
      C * std::pow(wall_strength_over_aperture(joint), D);
    return closure_mm / millimetres_per_metre;
  }

  double
  hyperbolic_normal_stiffness(const double initial_normal_stiffness,
                              const double maximum_closure,
                              const double normal_stress)
  {
    const double stiffening =
      1. + normal_stress / (maximum_closure * initial_normal_stiffness);
    return initial_normal_stiffness * stiffening * stiffening;
  }

  double
  hyperbolic_closure(const double initial_normal_stiffness,
                     const double maximum_closure,
                     const double normal_stress)
  {
    return normal_stress * maximum_closure /
           (initial_normal_stiffness * maximum_closure + normal_stress);
  }

  double
  barton_peak_friction_angle(const BartonBandisJoint &joint,
                             const double             normal_stress)
  {
    // JRC log10(JCS/sigma_n) is in degrees.
    const double roughness_degrees =
      joint.roughness_coefficient *
      std::log10(joint.wall_strength / normal_stress);
    return Units::degrees_to_radians(roughness_degrees) +
           joint.residual_friction_angle;
  }

  double
  barton_shear_stiffness(const BartonBandisJoint &joint,
                         const double             normal_stress,
                         const double             sheared_length)
  {
    // Peak shear displacement = sheared length / 100 (Barton 1982).
    constexpr double lengths_per_peak_displacement = 100.;
    return lengths_per_peak_displacement / sheared_length * normal_stress *
           std::tan(barton_peak_friction_angle(joint, normal_stress));
  }
} // namespace FloorBlock::Strength
