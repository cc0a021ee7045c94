#include <parameters/sections.h>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;

  void
  MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Bulk modulus",
                      "9e9",
                      Double(1.0e6, 1.0e13),
                      "Bulk modulus K of the intact rock (chapter Table 6.1: "
                      "9 GPa). Units: Pa.");
    prm.declare_entry("Shear modulus",
                      "6.7e9",
                      Double(1.0e6, 1.0e13),
                      "Shear modulus G of the intact rock (chapter Table 6.1: "
                      "6.7 GPa). Units: Pa.");
    prm.declare_entry("Density",
                      "2500",
                      Double(0, 2.0e4),
                      "Rock density; the chapter does not state it, 2500 is "
                      "typical of coal-measure sandstone. Units: kg/m^3.");
    prm.leave_subsection();
  }

  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    bulk_modulus  = prm.get_double("Bulk modulus");
    shear_modulus = prm.get_double("Shear modulus");
    density       = prm.get_double("Density");
    prm.leave_subsection();
    // With K > 0 and G > 0 (guaranteed by the patterns) nu lies in
    // (-1, 0.5) and E > 0: no further check is needed.
  }

  double
  MaterialParameters::youngs_modulus() const
  {
    return 9.0 * bulk_modulus * shear_modulus /
           (3.0 * bulk_modulus + shear_modulus);
  }

  double
  MaterialParameters::poissons_ratio() const
  {
    return (3.0 * bulk_modulus - 2.0 * shear_modulus) /
           (2.0 * (3.0 * bulk_modulus + shear_modulus));
  }
} // namespace FloorBlock::Parameters
