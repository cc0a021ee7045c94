#include <common/units.h>
#include <parameters/sections.h>

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
  }                                                 // namespace

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
                      "9e9",
                      Double(1.0e3, 1.0e16),
                      "Normal stiffness kn of the compliant joints (chapter "
                      "Table 6.1: 9 GPa/m). Units: Pa/m.");
    prm.declare_entry("Shear stiffness",
                      "6.7e9",
                      Double(1.0e3, 1.0e16),
                      "Shear stiffness ks of the compliant joints (chapter "
                      "Table 6.1: 6.7 GPa/m). Units: Pa/m.");
    prm.declare_entry("Law",
                      "compliant",
                      Selection("compliant|rigid"),
                      "Joint law: compliant (UDEC joint with kn, ks and "
                      "Coulomb slip) or rigid (exact non-penetration and "
                      "Coulomb friction). Units: none.");
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
    prm.leave_subsection();
  }
} // namespace FloorBlock::Parameters
