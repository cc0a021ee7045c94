#include <common/input_error.h>
#include <parameters/sections.h>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;

  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Corner size", "0.02", Double(1.0e-5, 10),
                      "Target element size at the block corners, where "
                      "contact concentrates. Units: m.");
    prm.declare_entry("Far size", "0.25", Double(1.0e-4, 100),
                      "Element size far from the corners. Units: m.");
    prm.declare_entry("Growth rate", "1.3", Double(1.01, 3),
                      "Ratio between the sizes of neighbouring elements on "
                      "the way from a corner to the far field. Units: none.");
    prm.declare_entry("Matching joints", "true", Bool(),
                      "Whether both sides of every joint get the same nodes "
                      "(node-to-node contact). false (non-matching sides) "
                      "is refused while Model/Blocks chooses the elastic "
                      "FEM, whose joints pair nodes one to one. Units: none.");
    prm.declare_entry(
      "Global refinements", "auto", Selection("auto|0|1|2|3|4|5|6"),
      "How many times deal.II halves every cell of the Gmsh mesh, new "
      "boundary vertices on the scene's curves (nested meshes: `converge "
      "--mode uniform` adds one per level). auto: none while the joints' "
      "compliance length E/kn is at least the corner rounding radius; "
      "otherwise (the rigid law, very stiff joints) enough halvings to "
      "bring Corner size down to the rounding radius, because then the "
      "corner fillet alone limits the contact concentration "
      "(src/scene/mesh_refinement.h). Units: none.");
    prm.declare_entry(
      "Cells per contact length", "8", Integer(0, 100),
      "Contact-zone sizing: cells of size c / N (not below Corner size) "
      "along both ends of every vertical joint, over 1.5 c from the "
      "corner, where c is the closed-form contact length of the face "
      "joint (Eq. 6.51; the shortest of the mechanisms that give one). "
      "So the ends of the contact zones sit in cells sized from the scene, "
      "not from the corner grading alone. 0: no contact-zone sizing "
      "(also when no mechanism gives a contact length). Units: none.");
    prm.leave_subsection();
  }

  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    corner_size     = prm.get_double("Corner size");
    far_size        = prm.get_double("Far size");
    growth_rate     = prm.get_double("Growth rate");
    matching_joints = prm.get_bool("Matching joints");
    cells_per_contact_length = prm.get_integer("Cells per contact length");
    const std::string refinements = prm.get("Global refinements");
    global_refinements =
      refinements == "auto" ?
        std::nullopt :
        std::optional<unsigned int>(std::stoul(refinements));
    prm.leave_subsection();

    if (corner_size > far_size)
      throw InputError("Mesh/Corner size", std::to_string(corner_size),
                       "must not exceed Mesh/Far size = " +
                         std::to_string(far_size) + " m");
  }
} // namespace FloorBlock::Parameters
