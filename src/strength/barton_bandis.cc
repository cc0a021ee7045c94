#include <common/units.h>
#include <strength/barton_bandis.h>

#include <cmath>
#include <limits>

namespace FloorBlock::Strength
{
  namespace
  {
    // The relations are fitted in MPa, mm and degrees. Inputs are converted
    // to those units on entry and results back to SI on return, here only.
    constexpr double millimetres_per_metre  = 1.0e3;
    constexpr double megapascals_per_pascal = 1.0 / Units::MPa;
    /// 1 MPa/mm = 1e6 Pa / 1e-3 m.
    constexpr double pascals_per_metre_per_megapascal_per_millimetre = 1.0e9;

    /**
     * K_ni = intercept + per_roughness JRC + per_strength JCS/a_j in MPa/mm
     * (Bandis, Lumsden and Barton 1983, fresh joints, first loading cycle).
     */
    struct FirstCycleStiffness
    {
      static constexpr double intercept     = -7.15;
      static constexpr double per_roughness = 1.75;
      static constexpr double per_strength  = 0.02; ///< per MPa/mm
    };

    /**
     * V_m = A + B JRC + C (JCS/a_j)^D in mm, as published for the first
     * cycle (ibid.); the third cycle's (-0.1032, -0.0074, 1.1350, -0.2510)
     * give the smaller closure of a joint already closed twice.
     */
    struct FirstCycleClosure
    {
      static constexpr double A = -0.2960;
      static constexpr double B = -0.0056;
      static constexpr double C = 2.2410;
      static constexpr double D = -0.2450;
    };

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
    const double stiffness_mpa_per_mm =
      FirstCycleStiffness::intercept +
      FirstCycleStiffness::per_roughness * joint.roughness_coefficient +
      FirstCycleStiffness::per_strength * wall_strength_over_aperture(joint);
    return stiffness_mpa_per_mm *
           pascals_per_metre_per_megapascal_per_millimetre;
  }

  double
  bandis_maximum_closure(const BartonBandisJoint &joint)
  {
    using Fit = FirstCycleClosure;
    const double closure_mm =
      Fit::A + Fit::B * joint.roughness_coefficient +
      Fit::C * std::pow(wall_strength_over_aperture(joint), Fit::D);
    return closure_mm / millimetres_per_metre;
  }

  double
  bandis_largest_aperture_for_stiffness(const double roughness_coefficient,
                                        const double wall_strength)
  {
    const double rest =
      FirstCycleStiffness::intercept +
      FirstCycleStiffness::per_roughness * roughness_coefficient;
    if (rest > 0.)
      return std::numeric_limits<double>::infinity();
    // 0.02 JCS / a_j > -rest, JCS in MPa, a_j in mm.
    return FirstCycleStiffness::per_strength * wall_strength *
           megapascals_per_pascal / (-rest) / millimetres_per_metre;
  }

  double
  bandis_smallest_aperture_for_closure(const double roughness_coefficient,
                                       const double wall_strength)
  {
    using Fit         = FirstCycleClosure;
    const double rest = Fit::A + Fit::B * roughness_coefficient;
    if (rest >= 0.)
      return 0.;
    // C (JCS/a_j)^D > -rest with D < 0: JCS/a_j below (-rest/C)^(1/D).
    const double largest_ratio = std::pow(-rest / Fit::C, 1. / Fit::D);
    return wall_strength * megapascals_per_pascal / largest_ratio /
           millimetres_per_metre;
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
