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
    prm.declare_entry("Radius",
                      "1",
                      Double(1e-4, 1e3),
                      "Radius R of the Hertz line contact (plane strain, "
                      "frictionless), modelled as Hertz's own problem: an "
                      "elastic half-space block on a rigid parabolic "
                      "obstacle x^2/(2R). Units: m.");
    prm.declare_entry("Line load",
                      "2e7",
                      Double(1, 1e12),
                      "Load P per unit length of the contact. Units: N/m.");
    prm.declare_entry("Young's modulus",
                      "1e10",
                      Double(1e6, 1e13),
                      "Young's modulus E of the elastic body. Units: Pa.");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Double(-0.99, 0.49),
                      "Poisson's ratio nu of the elastic body. Units: none.");
    prm.declare_entry("Cells per half-width",
                      "32",
                      Integer(4, 256),
                      "Contact cell size as a fraction of the closed-form "
                      "half-width a: cells of size a / N cover the contact "
                      "zone and grow away from it, so every radius, load "
                      "and modulus is resolved alike. 32 meets the half-"
                      "width within 0.5 % and the peak pressure within "
                      "0.1 % for every R, P and E with nu <= 0.4 (nu = "
                      "0.45: use Solver/FE degree = 2, where 16 meet it). "
                      "Units: none.");
    prm.leave_subsection();
    prm.enter_subsection("Patch");
    prm.declare_entry("Pressure",
                      "2e6",
                      Double(1, 1e9),
                      "Pressure on the top of two unit squares pressed "
                      "together over a flat joint (uses Joints/Law). "
                      "Units: Pa.");
    prm.leave_subsection();
    prm.enter_subsection("Incline");
    prm.declare_entry("Threshold margin",
                      "0.1",
                      Double(0.01, 0.9),
                      "The block is solved twice, at tan(alpha) = (1 - m) "
                      "tan(phi) (must stick) and (1 + m) tan(phi) (must "
                      "slip); phi = Joints/Bedding friction angle. "
                      "Units: none (relative to tan(phi)).");
    prm.leave_subsection();
    prm.enter_subsection("Two blocks");
    prm.declare_entry("Lateral pressure",
                      "4e5",
                      Double(1, 1e8),
                      "Pressure on the upper quarter of the free block's "
                      "outer side, pushing it against the fixed block. "
                      "Units: Pa.");
    prm.declare_entry("Cells per metre",
                      "4",
                      Integer(2, 32),
                      "Cells per metre of the structured block meshes. "
                      "Units: 1/m.");
    prm.leave_subsection();
    prm.enter_subsection("Punch");
    prm.declare_entry("Pressure",
                      "2e6",
                      Double(1, 1e10),
                      "Uniform pressure on the top of the square-ended "
                      "block pressed onto an elastically similar base "
                      "(uses Material/Bulk and Shear modulus; the "
                      "interface is always exact contact). Units: Pa.");
    prm.declare_entry("Corner refinements",
                      "12",
                      Integer(4, 16),
                      "Halvings of the 0.25 m cells around the block "
                      "corner: the smallest cells are 0.25 m / 2^n. "
                      "Units: none.");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  void
  VerifyParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verify");
    prm.enter_subsection("Hertz");
    hertz_radius               = prm.get_double("Radius");
    hertz_line_load            = prm.get_double("Line load");
    hertz_youngs_modulus       = prm.get_double("Young's modulus");
    hertz_poissons_ratio       = prm.get_double("Poisson's ratio");
    hertz_cells_per_half_width = prm.get_integer("Cells per half-width");
    prm.leave_subsection();
    prm.enter_subsection("Patch");
    patch_pressure = prm.get_double("Pressure");
    prm.leave_subsection();
    prm.enter_subsection("Incline");
    incline_margin = prm.get_double("Threshold margin");
    prm.leave_subsection();
    prm.enter_subsection("Two blocks");
    two_blocks_lateral_pressure = prm.get_double("Lateral pressure");
    two_blocks_cells_per_metre  = prm.get_integer("Cells per metre");
    prm.leave_subsection();
    prm.enter_subsection("Punch");
    punch_pressure           = prm.get_double("Pressure");
    punch_corner_refinements = prm.get_integer("Corner refinements");
    prm.leave_subsection();
    prm.leave_subsection();
  }
} // namespace FloorBlock::Parameters
