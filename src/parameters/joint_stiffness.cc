#include <common/input_error.h>
#include <common/units.h>
#include <parameters/sections.h>
#include <parameters/value_text.h>

#include <strength/barton_bandis.h>

#include <cmath>
#include <sstream>

namespace FloorBlock::Parameters
{
  namespace
  {
    // Barton and Choubey (1977) use the peak friction angle JRC log10(JCS /
    // sigma_n) + phi_r up to 70 deg; beyond, at low stress on rough, strong
    // walls, it overstates the strength, and at 90 deg tan is infinite.
    constexpr double largest_peak_friction_angle = 70.; // degrees

    // The compliant law's range for a given kn or ks (Joints/Normal
    // stiffness, Shear stiffness); derived values must meet it too.
    constexpr double smallest_stiffness = 1.0e3;  // Pa/m
    constexpr double largest_stiffness  = 1.0e16; // Pa/m

    constexpr double millimetres_per_metre = 1.0e3;

    /** @p value to @p digits significant digits. */
    std::string
    number(const double value, const int digits = 4)
    {
      std::ostringstream text;
      text.precision(digits);
      text << value;
      return text.str();
    }

    std::string
    metres(const double value)
    {
      return number(value) + " m";
    }

    /** The aperture given, or Barton's estimate from the strengths. */
    double
    initial_aperture(const BartonBandisEntries &entries,
                     const StrengthParameters  &strength)
    {
      if (entries.initial_aperture)
        return *entries.initial_aperture;
      const double aperture =
        Strength::barton_initial_aperture(entries.roughness_coefficient,
                                          entries.wall_strength,
                                          strength.intact_ucs);
      if (!(aperture > 0.))
        throw InputError("Joints/Initial aperture",
                         "auto = " + metres(aperture),
                         "a value in m: Barton's estimate JRC/5 (0.2 "
                         "sigma_c/JCS - 0.1) mm needs Joints/Joint roughness "
                         "coefficient > 0");
      return aperture;
    }

    /** Refuses an aperture outside the range where the Bandis fits give a
     * positive initial stiffness and maximum closure. */
    void
    check_aperture(const Strength::BartonBandisJoint &joint,
                   const bool                         aperture_auto)
    {
      const double largest = Strength::bandis_largest_aperture_for_stiffness(
        joint.roughness_coefficient, joint.wall_strength);
      const double smallest = Strength::bandis_smallest_aperture_for_closure(
        joint.roughness_coefficient, joint.wall_strength);
      const std::string value =
        (aperture_auto ? "auto = " : "") + metres(joint.initial_aperture);
      const std::string range =
        "between " + metres(smallest) + " and " +
        (std::isinf(largest) ? std::string("any larger value") :
                               metres(largest)) +
        " for this JRC and JCS: ";
      if (!(Strength::bandis_initial_normal_stiffness(joint) > 0.))
        throw InputError("Joints/Initial aperture",
                         value,
                         range +
                           "a wider one gives K_ni = -7.15 + 1.75 JRC + 0.02 "
                           "JCS/a_j <= 0 (Bandis et al. 1983)");
      if (!(Strength::bandis_maximum_closure(joint) > 0.))
        throw InputError("Joints/Initial aperture",
                         value,
                         range +
                           "a narrower one gives V_m = -0.2960 - 0.0056 JRC "
                           "+ 2.2410 (JCS/a_j)^-0.2450 <= 0 (Bandis et al. "
                           "1983)");
    }

    /** Refuses a normal stress outside Barton's peak-angle range and one
     * that would close the joint by more than its aperture. */
    void
    check_normal_stress(const Strength::BartonBandisJoint &joint,
                        const double                       normal_stress)
    {
      const double peak = Units::radians_to_degrees(
        Strength::barton_peak_friction_angle(joint, normal_stress));
      const double jrc = joint.roughness_coefficient;
      const double residual =
        Units::radians_to_degrees(joint.residual_friction_angle);
      if (jrc == 0. && !(peak > 0.))
        throw InputError("Joints/Residual friction angle",
                         "0",
                         "above 0 deg: a smooth joint (JRC 0) has phi_peak "
                         "= phi_r, and ks = 0 without friction");
      if (peak > 0. && peak <= largest_peak_friction_angle)
        return;
      const double lowest =
        joint.wall_strength *
        std::pow(10., -(largest_peak_friction_angle - residual) / jrc);
      const double highest =
        joint.wall_strength * std::pow(10., residual / jrc);
      throw InputError("Joints/Normal stress for stiffness",
                       pascals(normal_stress),
                       "from " + pascals(lowest) + " to below " +
                         pascals(highest) +
                         " for this JRC, JCS and phi_r: there Barton's "
                         "phi_peak = JRC log10(JCS / sigma_n) + phi_r (here " +
                         number(peak, 3) + " deg) lies in (0, " +
                         number(largest_peak_friction_angle) + "] deg");
    }

    /** Refuses a stress that closes the joint beyond its aperture. */
    void
    check_closure(const Strength::BartonBandisJoint &joint,
                  const double                       normal_stress)
    {
      const double initial  = Strength::bandis_initial_normal_stiffness(joint);
      const double maximum  = Strength::bandis_maximum_closure(joint);
      const double aperture = joint.initial_aperture;
      if (Strength::hyperbolic_closure(initial, maximum, normal_stress) <
          aperture)
        return;
      // sigma V_m / (K_ni V_m + sigma) = a_j solved for sigma (V_m > a_j).
      const double limit = aperture * initial * maximum / (maximum - aperture);
      throw InputError("Joints/Normal stress for stiffness",
                       pascals(normal_stress),
                       "below " + pascals(limit) +
                         ", where the Bandis hyperbola closes the joint by "
                         "its whole aperture a_j = " +
                         metres(aperture));
    }

    void
    check_stiffness(const double normal, const double shear)
    {
      for (const double value : {normal, shear})
        if (!(value >= smallest_stiffness && value <= largest_stiffness))
          throw InputError("Joints/Stiffness source",
                           "Barton-Bandis",
                           "joint data whose kn = " + number(normal, 3) +
                             " Pa/m and ks = " + number(shear, 3) +
                             " Pa/m lie between " + number(smallest_stiffness) +
                             " and " + number(largest_stiffness) +
                             " Pa/m, the range of a given Normal and Shear "
                             "stiffness");
    }

    /** The derived stiffness and its inputs in words. */
    std::string
    origin_text(const Strength::BartonBandisJoint &joint,
                const BartonBandisEntries         &entries,
                const double                       sheared_length,
                const double                       normal_stiffness,
                const double                       shear_stiffness)
    {
      const double initial = Strength::bandis_initial_normal_stiffness(joint);
      const double maximum = Strength::bandis_maximum_closure(joint);
      return "Barton-Bandis at sigma_n = " +
             number(entries.normal_stress / Units::MPa, 3) +
             " MPa: kn = " + number(normal_stiffness, 3) +
             " Pa/m, ks = " + number(shear_stiffness, 3) + " Pa/m (JRC " +
             number(joint.roughness_coefficient) + ", JCS " +
             number(joint.wall_strength / Units::MPa, 3) + " MPa, a_j " +
             number(joint.initial_aperture * millimetres_per_metre, 3) + " mm" +
             (entries.initial_aperture ? "" : " auto") + ", phi_r " +
             number(Units::radians_to_degrees(joint.residual_friction_angle)) +
             " deg, L_x " + number(sheared_length) + " m" +
             (entries.sheared_length ? "" : " auto = Geometry/Block height") +
             "; K_ni = " + number(initial, 3) +
             " Pa/m, V_m = " + number(maximum * millimetres_per_metre, 3) +
             " mm)";
    }
  } // namespace

  void
  JointParameters::resolve_stiffness(const GeometryParameters &geometry,
                                     const StrengthParameters &strength)
  {
    stiffness_origin.clear();
    if (stiffness_source != JointStiffnessSource::barton_bandis)
      return;
    const BartonBandisEntries &entries = barton_bandis;
    // A joint wall is at most as strong as the rock it cuts; above twice
    // sigma_c Barton's aperture estimate would turn negative.
    if (entries.wall_strength > strength.intact_ucs)
      throw InputError("Joints/Joint wall strength",
                       pascals(entries.wall_strength),
                       "at most Strength/Intact UCS = " +
                         pascals(strength.intact_ucs) +
                         " (equal for fresh walls, lower for weathered)");
    const Strength::BartonBandisJoint joint{entries.roughness_coefficient,
                                            entries.wall_strength,
                                            initial_aperture(entries, strength),
                                            entries.residual_friction_angle};
    check_aperture(joint, !entries.initial_aperture);
    check_normal_stress(joint, entries.normal_stress);
    check_closure(joint, entries.normal_stress);

    const double length =
      entries.sheared_length.value_or(geometry.block_height);
    normal_stiffness = Strength::hyperbolic_normal_stiffness(
      Strength::bandis_initial_normal_stiffness(joint),
      Strength::bandis_maximum_closure(joint),
      entries.normal_stress);
    shear_stiffness =
      Strength::barton_shear_stiffness(joint, entries.normal_stress, length);
    check_stiffness(normal_stiffness, shear_stiffness);
    stiffness_origin =
      origin_text(joint, entries, length, normal_stiffness, shear_stiffness);
  }
} // namespace FloorBlock::Parameters
