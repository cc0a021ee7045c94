#include <common/input_error.h>
#include <common/units.h>
#include <parameters/auto_or_double.h>
#include <parameters/sections.h>

#include <string>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Selection;

  namespace
  {
    // Friction must stay below 90 deg (tan would be infinite); 89.9 keeps
    // tan(phi) finite with margin.
    constexpr double largest_friction_angle = 89.9; // degrees

    // Chapter Table 6.1; also what the given entries must stay at while
    // the stiffness comes from the joint data.
    const std::string table_normal_stiffness = "9e9";   // Pa/m
    const std::string table_shear_stiffness  = "6.7e9"; // Pa/m

    /** The Barton-Bandis entries: the joint data and where to evaluate. */
    void
    declare_barton_bandis_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Stiffness source",
        "given",
        Selection("given|Barton-Bandis"),
        "Where kn and ks of the compliant law come from. given: Normal "
        "stiffness and Shear stiffness. Barton-Bandis: from the joint data "
        "(Joint roughness coefficient, Joint wall strength, Initial "
        "aperture, Residual friction angle, Sheared length) at Normal "
        "stress for stiffness (Bandis, Lumsden and Barton 1983; Barton, "
        "Bandis and Bakhtar 1985; src/strength/README.md); Normal stiffness "
        "and Shear stiffness must then keep their defaults and Law must be "
        "compliant. Every command that reads the scene prints the derived "
        "values and parameters.prm notes them. Units: none.");
      prm.declare_entry(
        "Joint roughness coefficient",
        "8",
        Double(0, 20),
        "JRC of the joint walls (Barton and Choubey 1977: 0 smooth and "
        "planar, 20 very rough). Default: a rough coal-measure joint "
        "(assumed). The stiffness fits are calibrated for 5-15. Read for "
        "Stiffness source = Barton-Bandis. Units: none.");
      prm.declare_entry(
        "Joint wall strength",
        "20e6",
        Double(1e5, 5e8),
        "JCS, uniaxial compressive strength of the joint walls, at most "
        "Strength/Intact UCS (equal for fresh walls, lower for weathered "
        "ones). Default: weathered walls at half the default siltstone's "
        "UCS (assumed). The fits are calibrated for 22-182 MPa. Read for "
        "Stiffness source = Barton-Bandis. Units: Pa.");
      prm.declare_entry(
        "Initial aperture",
        "auto",
        AutoOrDouble(1e-6, 1e-2),
        "a_j, mean aperture of the unloaded joint. auto: Barton's estimate "
        "JRC/5 (0.2 sigma_c/JCS - 0.1) mm with sigma_c = Strength/Intact UCS "
        "(0.48 mm for the defaults; calibrated for 0.1-0.6 mm). Read for "
        "Stiffness source = Barton-Bandis. Units: m.");
      prm.declare_entry(
        "Residual friction angle",
        "25",
        Double(0, 60),
        "phi_r of the joint walls, in Barton's peak friction angle JRC "
        "log10(JCS/sigma_n) + phi_r that sets ks (most rocks 20-35 deg; "
        "assumed 25). Slip keeps Bedding and Vertical friction angle. Read "
        "for Stiffness source = Barton-Bandis. Units: degrees.");
      prm.declare_entry(
        "Normal stress for stiffness",
        "1e6",
        Double(1e3, 5e8),
        "sigma_n at which kn (the closure hyperbola's tangent) and ks "
        "(Barton's peak secant) are evaluated: the order of the joints' "
        "mean normal stress (the default scene's face joint carries about "
        "2.7 MN/m over its 2 m). The compliant law is linear, one kn and ks "
        "for every joint and increment. Read for Stiffness source = "
        "Barton-Bandis. Units: Pa.");
      prm.declare_entry(
        "Sheared length",
        "auto",
        AutoOrDouble(1e-2, 100.),
        "L_x of Barton's ks = (100 / L_x) sigma_n tan(phi_peak): the "
        "joint's length along the shear, 1 % of which is the peak shear "
        "displacement. auto: Geometry/Block height, the vertical joints' "
        "length (the bedding joints, one block width long, share the same "
        "ks). Read for Stiffness source = Barton-Bandis. Units: m.");
    }
    /**
     * The Barton-Bandis entries into @p joints (SI), and the checks within
     * the subsection: the joint data contradict the rigid law and a given
     * stiffness other than the default.
     */
    void
    parse_barton_bandis_entries(ParameterHandler &prm, JointParameters &joints)
    {
      BartonBandisEntries &entries = joints.barton_bandis;
      entries.roughness_coefficient =
        prm.get_double("Joint roughness coefficient");
      entries.wall_strength = prm.get_double("Joint wall strength");
      entries.initial_aperture.reset();
      if (!is_auto(prm.get("Initial aperture")))
        entries.initial_aperture = prm.get_double("Initial aperture");
      entries.residual_friction_angle =
        Units::degrees_to_radians(prm.get_double("Residual friction angle"));
      entries.normal_stress = prm.get_double("Normal stress for stiffness");
      entries.sheared_length.reset();
      if (!is_auto(prm.get("Sheared length")))
        entries.sheared_length = prm.get_double("Sheared length");
      if (joints.stiffness_source != JointStiffnessSource::barton_bandis)
        return;

      // The rigid law has no stiffness to derive.
      if (joints.law == Contact::JointLawKind::rigid)
        throw InputError("Joints/Stiffness source",
                         "Barton-Bandis",
                         "given while Joints/Law = rigid: the rigid law has no "
                         "kn and ks (set Law = compliant to use the joint "
                         "data)");
      // ParameterHandler cannot tell a default from a value written out: a
      // given stiffness other than the default is what contradicts the joint
      // data; the default itself may stand in a scene file.
      for (const auto &[entry, table_value] :
           {std::pair{"Normal stiffness", table_normal_stiffness},
            std::pair{"Shear stiffness", table_shear_stiffness}})
        if (prm.get_double(entry) != std::stod(table_value))
          throw InputError(std::string("Joints/") + entry,
                           prm.get(entry),
                           "its default " + table_value +
                             " (unused) while Joints/Stiffness source = "
                             "Barton-Bandis, which derives kn and ks from "
                             "the joint data; or Stiffness source = given");
    }
  } // namespace

  void
  JointParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Joints");
    prm.declare_entry("Bedding friction angle",
                      "30",
                      Double(0, largest_friction_angle),
                      "Friction angle phi_h of the failed bedding plane. "
                      "Units: degrees.");
    prm.declare_entry("Vertical friction angle",
                      "30",
                      Double(0, largest_friction_angle),
                      "Friction angle phi_v of the vertical fractures. "
                      "Units: degrees.");
    prm.declare_entry(
      "Cohesion",
      "0",
      Double(0, 1.0e9),
      "Cohesion of all joints (chapter Table 6.1: 0). Units: Pa.");
    prm.declare_entry("Tensile strength",
                      "0",
                      Double(0, 1.0e9),
                      "Tensile strength of all joints. Units: Pa.");
    prm.declare_entry("Normal stiffness",
                      table_normal_stiffness,
                      Double(1.0e3, 1.0e16),
                      "Normal stiffness kn of the compliant joints (chapter "
                      "Table 6.1: 9 GPa/m), for Stiffness source = given. "
                      "Units: Pa/m.");
    prm.declare_entry("Shear stiffness",
                      table_shear_stiffness,
                      Double(1.0e3, 1.0e16),
                      "Shear stiffness ks of the compliant joints (chapter "
                      "Table 6.1: 6.7 GPa/m), for Stiffness source = given. "
                      "Units: Pa/m.");
    prm.declare_entry("Law",
                      "compliant",
                      Selection("compliant|rigid"),
                      "Joint law: compliant (UDEC joint with kn, ks and "
                      "Coulomb slip) or rigid (exact non-penetration and "
                      "Coulomb friction). Units: none.");
    declare_barton_bandis_entries(prm);
    prm.leave_subsection();
  }

  void
  JointParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Joints");
    bedding_friction_angle =
      Units::degrees_to_radians(prm.get_double("Bedding friction angle"));
    vertical_friction_angle =
      Units::degrees_to_radians(prm.get_double("Vertical friction angle"));
    cohesion         = prm.get_double("Cohesion");
    tensile_strength = prm.get_double("Tensile strength");
    normal_stiffness = prm.get_double("Normal stiffness");
    shear_stiffness  = prm.get_double("Shear stiffness");
    law = prm.get("Law") == "rigid" ? Contact::JointLawKind::rigid :
                                      Contact::JointLawKind::compliant;
    stiffness_source = prm.get("Stiffness source") == "Barton-Bandis" ?
                         JointStiffnessSource::barton_bandis :
                         JointStiffnessSource::given;
    parse_barton_bandis_entries(prm, *this);
    prm.leave_subsection();
  }

} // namespace FloorBlock::Parameters
