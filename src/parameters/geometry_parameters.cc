#include <common/input_error.h>
#include <parameters/sections.h>
#include <parameters/value_text.h>

#include <algorithm>
#include <string>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;

  namespace
  {
    // Sizes below a millimetre or above a kilometre are typos, not scenes.
    constexpr double smallest_length = 1.0e-3; // m
    constexpr double largest_length  = 1.0e3;  // m
  }                                            // namespace

  void
  GeometryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry("Number of blocks",
                      "6",
                      Integer(1, 99),
                      "Number n of free floor blocks between the free end and "
                      "the fixed face block. Units: none.");
    prm.declare_entry("Block width",
                      "1.0",
                      Double(smallest_length, largest_length),
                      "Block width L perpendicular to the face (spacing of the "
                      "vertical fractures). Units: m.");
    prm.declare_entry("Block height",
                      "2.0",
                      Double(smallest_length, largest_length),
                      "Block height H, from the failed bedding to the floor "
                      "surface. Units: m.");
    prm.declare_entry("Support width",
                      "1.5",
                      Double(smallest_length, largest_length),
                      "Width b of one powered support along the face; the "
                      "plane-strain results per metre are multiplied by b for "
                      "forces and areas 'over b'. The chapter does not state "
                      "it; 1.5 m is a common shield width. Units: m.");
    prm.declare_entry(
      "Face block width",
      "1.0",
      Double(smallest_length, largest_length),
      "Width of the fixed face block next to block n. Units: m.");
    prm.declare_entry("Base thickness",
                      "1.0",
                      Double(smallest_length, largest_length),
                      "Thickness of the bedding layer below the blocks on "
                      "which they slide. Units: m.");
    prm.declare_entry("Corner rounding radius",
                      "0.01",
                      Double(0, largest_length),
                      "Corner rounding of the blocks, as UDEC's rounding "
                      "length: each fillet starts this far from the corner "
                      "along the vertical side, so both sides of a joint keep "
                      "the same straight part. It is the fillet radius at a "
                      "right-angled corner (r tan(theta/2) at an interior "
                      "angle theta). 0 = sharp corners, whose pointwise "
                      "contact stress is singular. Must be below a quarter of "
                      "the smallest block edge. Units: m.");
    prm.declare_entry("Dimension",
                      "2",
                      dealii::Patterns::Selection("2|3"),
                      "2: plane strain, per metre of face. 3: the 2D "
                      "assembly extruded along the face over Face length "
                      "(src/geometry/extruded_assembly.h): `mesh` "
                      "builds it (meshes/<scene>_3d.msh) and `solve` solves "
                      "it on one process, reporting forces per metre of "
                      "face; run, converge and sweep --fem refuse it. "
                      "Units: none.");
    prm.declare_entry("Face length",
                      "4.5",
                      Double(smallest_length, largest_length),
                      "Length of the 3D assembly along the face (z), used "
                      "when Dimension = 3; 4.5 m = 3 b for the default "
                      "support width. Units: m.");
    prm.declare_entry("End faces",
                      "plane strain",
                      dealii::Patterns::Selection("plane strain|free"),
                      "Boundary condition on the two end faces of a 3D "
                      "scene (z = 0 and z = Face length), used when "
                      "Dimension = 3. plane strain: u_z = 0 on both, x and "
                      "y free, as if the face continued beyond them; the 3D "
                      "answer is then the 2D one. free: no condition, the "
                      "assembly ends there. Units: none.");
    prm.leave_subsection();
  }

  void
  GeometryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    n_blocks               = prm.get_integer("Number of blocks");
    block_width            = prm.get_double("Block width");
    block_height           = prm.get_double("Block height");
    support_width          = prm.get_double("Support width");
    face_block_width       = prm.get_double("Face block width");
    base_thickness         = prm.get_double("Base thickness");
    corner_rounding_radius = prm.get_double("Corner rounding radius");
    dimension              = selected_count(prm.get("Dimension"), "Geometry/Dimension", "2 or 3");
    face_length            = prm.get_double("Face length");
    end_faces              = prm.get("End faces") == "free" ?
                               Geometry::EndFaces::free :
                               Geometry::EndFaces::plane_strain;
    prm.leave_subsection();

    // A fillet larger than a quarter edge would consume the straight joint
    // that the contact and the closed forms both rely on.
    const double largest_radius =
      0.25 * std::min({block_width, block_height, face_block_width});
    if (corner_rounding_radius >= largest_radius)
      throw InputError("Geometry/Corner rounding radius",
                       std::to_string(corner_rounding_radius),
                       "must be >= 0 and < a quarter of the smallest block "
                       "edge, here " +
                         std::to_string(largest_radius) + " m");
  }
} // namespace FloorBlock::Parameters
