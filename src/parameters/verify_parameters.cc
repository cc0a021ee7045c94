#include <parameters/sections.h>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;

  void
  VerifyParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verify");
    prm.enter_subsection("Hertz");
    prm.declare_entry("Radius", "1", Double(1e-4, 1e3),
                      "Radius R of the elastic cylinder pressed on a rigid "
                      "flat (plane strain, frictionless). Units: m.");
    prm.declare_entry("Line load", "2e7", Double(1, 1e12),
                      "Load P per unit length of the cylinder. Units: N/m.");
    prm.declare_entry("Young's modulus", "1e10", Double(1e6, 1e13),
                      "Young's modulus E of the cylinder. Units: Pa.");
    prm.declare_entry("Poisson's ratio", "0.3", Double(-0.99, 0.49),
                      "Poisson's ratio nu of the cylinder. Units: none.");
    prm.declare_entry("Mesh level", "6", Integer(2, 10),
                      "Local refinements towards the contact point; each "
                      "halves the cell size there. Units: none.");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  void
  VerifyParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verify");
    prm.enter_subsection("Hertz");
    hertz_radius         = prm.get_double("Radius");
    hertz_line_load      = prm.get_double("Line load");
    hertz_youngs_modulus = prm.get_double("Young's modulus");
    hertz_poissons_ratio = prm.get_double("Poisson's ratio");
    hertz_mesh_level     = prm.get_integer("Mesh level");
    prm.leave_subsection();
    prm.leave_subsection();
  }
} // namespace FloorBlock::Parameters
