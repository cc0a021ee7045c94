#include <analytic/floor_shape.h>
#include <common/units.h>
#include <parameters/sections.h>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Selection;

  void
  BeddingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Bedding");
    prm.declare_entry("Shape",
                      "parabolic",
                      Selection("planar|parabolic"),
                      "Shape of the failed bedding plane: planar (constant "
                      "inclination) or parabolic y = x^2/k with x measured "
                      "from the face. Units: none.");
    prm.declare_entry(
      "Inclination",
      "1",
      Double(-60, 60),
      "Inclination alpha of a planar bedding, positive when the "
      "bedding rises away from the face (the chapter's sense: "
      "the base pushes the blocks toward the face). The "
      "chapter's planar quotes imply a nearly level bed. "
      "Units: degrees.");
    prm.declare_entry("Curvature",
                      "400",
                      Double(1, 1.0e6),
                      "Parameter k of a parabolic bedding y = x^2/k (the "
                      "chapter uses 400, 200, 100, 50). Units: m.");
    prm.declare_entry("Floor uplift reading",
                      "lifted",
                      Selection("inclined|lifted"),
                      "Which of the chapter's readings of floor uplift the "
                      "scene uses: inclined (the bedding is already planar-"
                      "inclined or parabolic and the blocks stand on it, as "
                      "the closed forms assume) or lifted (the mesh starts "
                      "flat and the FEM lifts the bedding with the planar or "
                      "parabolic profile). Units: none.");
    prm.declare_entry("Base",
                      "elastic",
                      Selection("elastic|rigid"),
                      "What the blocks stand on: elastic (a base layer of "
                      "Geometry/Base thickness, the rock of Material, its "
                      "bottom moved by the uplift) or rigid (a rigid "
                      "half-plane below a flat bedding, moved by the uplift; "
                      "the face block stands on a fixed support of its own "
                      "and does not touch it). Units: none.");
    prm.declare_entry("Frame dip",
                      "0",
                      Double(0, 60),
                      "Dip of the model's frame: x runs along the bedding "
                      "away from the face and the frame is turned so that "
                      "moving in +x goes down at this angle. Gravity and "
                      "vertical support loads act along the true vertical, "
                      "(sin, -cos) of this angle in the frame. 0: x "
                      "horizontal. Units: degrees.");
    prm.leave_subsection();
  }

  bool
  BeddingParameters::flat_in_mesh() const
  {
    return floor_uplift == Geometry::FloorUplift::lifted_flat_bedding ||
           (shape == Geometry::BeddingShape::planar && inclination == 0.);
  }

  double
  BeddingParameters::rise_at_free_end(const unsigned int n_blocks,
                                      const double       block_width) const
  {
    if (shape == Geometry::BeddingShape::parabolic)
      return Analytic::parabolic_bedding_rise(n_blocks, block_width, curvature);
    return Analytic::planar_bedding_rise(n_blocks, block_width, inclination);
  }

  void
  BeddingParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Bedding");
    shape = prm.get("Shape") == "planar" ? Geometry::BeddingShape::planar :
                                           Geometry::BeddingShape::parabolic;
    floor_uplift = prm.get("Floor uplift reading") == "lifted" ?
                     Geometry::FloorUplift::lifted_flat_bedding :
                     Geometry::FloorUplift::inclined_bedding;
    inclination  = Units::degrees_to_radians(prm.get_double("Inclination"));
    curvature    = prm.get_double("Curvature");
    rigid_base   = prm.get("Base") == "rigid";
    frame_dip    = Units::degrees_to_radians(prm.get_double("Frame dip"));
    prm.leave_subsection();
  }
} // namespace FloorBlock::Parameters
