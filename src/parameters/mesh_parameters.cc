#include <common/input_error.h>
#include <parameters/sections.h>
#include <parameters/value_text.h>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::MultipleSelection;
  using dealii::Patterns::Selection;

  namespace
  {
    /** The mesh sizes, the joints' meshing and the contact-zone sizing. */
    void
    declare_mesh_sizes(ParameterHandler &prm)
    {
      prm.declare_entry("Corner size",
                        "0.02",
                        Double(1.0e-5, 10),
                        "Target element size at the block corners, where "
                        "contact concentrates. Units: m.");
      prm.declare_entry("Far size",
                        "0.25",
                        Double(1.0e-4, 100),
                        "Element size far from the corners. Units: m.");
      prm.declare_entry("Growth rate",
                        "1.3",
                        Double(1.01, 3),
                        "Ratio between the sizes of neighbouring elements on "
                        "the way from a corner to the far field. Units: none.");
      prm.declare_entry(
        "Matching joints",
        "true",
        Bool(),
        "Whether both sides of every joint get the same nodes "
        "(node-to-node contact). false (non-matching sides) "
        "is refused while Model/Blocks chooses the elastic "
        "FEM, whose joints pair nodes one to one. Units: none.");
      prm.declare_entry(
        "Global refinements",
        "auto",
        Selection("auto|0|1|2|3|4|5|6"),
        "How many times deal.II halves every cell of the Gmsh mesh, new "
        "boundary vertices on the scene's curves (nested meshes: `converge "
        "--mode uniform` adds one per level). auto: none while the joints' "
        "compliance length E/kn is at least the corner rounding radius; "
        "otherwise (the rigid law, very stiff joints) enough halvings to "
        "bring Corner size down to the rounding radius, because then the "
        "corner fillet alone limits the contact concentration "
        "(src/scene/mesh_sizing.h). Units: none.");
      prm.declare_entry(
        "Cells per critical distance",
        "0",
        Integer(0, 64),
        "Critical-distance sizing: cells of size L / N (Strength/Critical "
        "distance; not below 2.5e-4 of the smaller block side) along the "
        "bisectors of both top corners of every vertical joint, out to 1.5 "
        "L (Gmsh grades towards them, then deal.II halves every cell the "
        "paths cross until it is within sqrt(2) of L / N), so that the floor safety factor's stresses at L/2 and over L "
        "(src/safety/) are read from cells smaller than L; params/default.prm "
        "sets 16, with which the line method's factor on the default scene "
        "changes by less than 0.2 % per halving of every cell "
        "(results/FINDINGS.md, section 13). 0: none; the safety factor is "
        "then reported as unresolved wherever the corner cells exceed L/4. "
        "Units: none.");
      prm.declare_entry(
        "Cells per contact length",
        "8",
        Integer(0, 100),
        "Contact-zone sizing: cells of size c / N (not below Corner size) "
        "along both ends of every vertical joint, over 1.5 c from the "
        "corner, where c is the closed-form contact length of the face "
        "joint (Eq. 6.51; the shortest of the mechanisms that give one). "
        "Where Eq. 6.51 has no answer (or describes another scene), a 2D "
        "scene is first solved on its plain mesh and each vertical joint's "
        "computed contact zone, with c/2 beyond its ends, gets cells of its "
        "own c / N. So the ends of the contact zones sit in cells sized "
        "from the scene, not from the corner grading alone; fem.json "
        "mesh.contact_zone_sizing says which. 0: no contact-zone sizing. "
        "Units: none.");
    }

    /** `run`'s accuracy loop (target, figures, levels, time budget) and
     * the 3D slice size. */
    void
    declare_accuracy_loop(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Target relative error",
        "0.01",
        Double(1e-6, 1),
        "Accuracy as the input: `run` solves on the mesh sized from the "
        "scene, then refines it adaptively (hanging nodes at the contact "
        "ends, along large traction jumps and where the Kelly indicator is "
        "largest) level by level, until the estimated error of every target "
        "figure of the face joint (6 times its difference to the next "
        "level, plus a contact end's location uncertainty) is at most this "
        "fraction of the figure, or the levels or the time budget run out "
        "(then it says so, with the estimate reached). The figures are "
        "reported from the coarser of the last two levels, with that "
        "estimate (src/studies/accuracy_loop.h). Units: none (0.01 = 1 %).");
      prm.declare_entry(
        "Target figures",
        "normal force, contact length",
        MultipleSelection("normal force|contact length|sigma_max|"
                          "sigma_max averaged"),
        "The face-joint figures Target relative error applies to; the others "
        "are reported with their estimate but do not refine the mesh. The "
        "peaks are not targets by default: with exact contact the pointwise "
        "peak at a corner has no mesh limit, and the averaged one depends on "
        "Solver/Averaging length (see `floorblock corner`). Units: none.");
      prm.declare_entry(
        "Maximum refinement levels",
        "6",
        Integer(1, 20),
        "Largest number of adaptive levels `run` solves after the first "
        "mesh (1: one refined solve, only for the estimate), not counting "
        "the level that confirms a checked pair which met the target "
        "(src/studies/target_loop.h). Units: none.");
      prm.declare_entry(
        "Refinement time budget",
        "1800",
        Double(1, 1e6),
        "Bounds `run`'s wall time, counted from the command's start and "
        "shared by both FE degrees of a race: a level or check whose "
        "forecast would end past it is not started, and one that runs past "
        "it stops at its next load increment, so that the command ends "
        "within the budget and one increment; the last checked level is "
        "reported. The command's first solve always runs to its end. The "
        "default lets the exact law on the default scene reach 1 %: level "
        "5's check meets it after about 610 s on a 2-core machine, and "
        "level 6's check, the next candidate, is forecast at about 1200 s "
        "(results/FINDINGS.md). Units: s.");
      prm.declare_entry(
        "Slice size",
        "0.25",
        Double(1e-3, 100),
        "Thickness of the slices a 3D scene (Geometry/Dimension = 3) is "
        "extruded through along the face: ceil(Face length / Slice size) "
        "equal slices. Units: m.");
    }

  } // namespace

  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    declare_mesh_sizes(prm);
    declare_accuracy_loop(prm);
    prm.leave_subsection();
  }

  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    corner_size                   = prm.get_double("Corner size");
    far_size                      = prm.get_double("Far size");
    growth_rate                   = prm.get_double("Growth rate");
    matching_joints               = prm.get_bool("Matching joints");
    cells_per_contact_length      = prm.get_integer("Cells per contact length");
    cells_per_critical_distance   = prm.get_integer("Cells per critical distance");
    const std::string refinements = prm.get("Global refinements");
    global_refinements            = refinements == "auto" ?
                                      std::nullopt :
                                      std::optional<unsigned int>(selected_count(refinements, "Mesh/Global refinements", "auto or 0 to 6"));
    target_relative_error         = prm.get_double("Target relative error");
    target_figures.clear();
    for (const std::string &name :
         dealii::Utilities::split_string_list(prm.get("Target figures")))
      target_figures.push_back(
        name == "normal force"   ? TargetFigure::normal_force :
        name == "contact length" ? TargetFigure::contact_length :
        name == "sigma_max"      ? TargetFigure::sigma_max :
                                   TargetFigure::sigma_max_averaged);
    max_refinement_levels  = prm.get_integer("Maximum refinement levels");
    refinement_time_budget = prm.get_double("Refinement time budget");
    slice_size             = prm.get_double("Slice size");
    prm.leave_subsection();

    if (corner_size > far_size)
      throw InputError("Mesh/Corner size",
                       std::to_string(corner_size),
                       "must not exceed Mesh/Far size = " +
                         std::to_string(far_size) + " m");
  }
} // namespace FloorBlock::Parameters
