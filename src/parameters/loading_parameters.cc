#include <common/input_error.h>
#include <common/units.h>
#include <parameters/auto_or_double.h>
#include <parameters/sections.h>

#include <set>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;
  using dealii::Patterns::Selection;

  namespace
  {
    constexpr unsigned int largest_block_count = 99;
    // Bounds of Geometry/Face length (geometry_parameters.cc): a footprint
    // longer than a kilometre of face is a typo, not a scene.
    constexpr double largest_footprint = 1.0e3; // m
    /** Loading/Footprint offset's value for "centred on the face". */
    constexpr double centred_offset = -1.;
  } // namespace

  void
  LoadingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    prm.declare_entry("Gravity",
                      "9.81",
                      Double(0, 100),
                      "Gravitational acceleration acting on the rock. "
                      "Units: m/s^2.");
    prm.declare_entry("Support load",
                      "650",
                      Double(0, 1.0e5),
                      "Total load of one powered support (chapter: 650 t), "
                      "spread evenly over the loaded blocks and over the "
                      "support width b. Converted with standard gravity "
                      "9.80665 m/s^2. Units: t (tonnes-force).");
    prm.declare_entry(
      "Support load direction",
      "vertical",
      Selection("vertical|normal to block top"),
      "Direction of the support load on a block top: "
      "straight down with the same total per block on an "
      "inclined top (the closed forms' W_i + P_i), or as a "
      "pressure normal to the top (a shield base resting on "
      "it). Only differs where the block tops are inclined "
      "(Bedding/Floor uplift reading = inclined). Units: none.");
    prm.declare_entry(
      "Loaded blocks from face",
      "4,5,6",
      List(Integer(1, largest_block_count), 0, largest_block_count, ","),
      "Blocks under the support, counted from the face "
      "(1 = the block next to the face block, as the chapter counts "
      "supports: \"the 4th, 5th and 6th block from the face\"); "
      "comma-separated, may be empty. The output numbers blocks the other "
      "way, from the free end (block n is next to the face block), and "
      "report.md and `analytic` name the loaded blocks in that numbering. "
      "Units: none.");
    prm.declare_entry(
      "Floor lift",
      "auto",
      AutoOrDouble(0, 10),
      "Size of the base motion in the floor-uplift stage of the FEM: the "
      "translation distance (vertical, dip modes), the rise of the face end "
      "(tilt), the rise of the free end (parabola, slope). auto: the rise of "
      "the bedding the closed forms stand the blocks on, from the face to "
      "the free end x = nL: (nL)^2/k on a parabolic bed, nL tan(alpha) on a "
      "planar one (0 where that is negative). With Bedding/Floor uplift "
      "reading = lifted and Uplift mode = parabola (parabolic bed) or slope "
      "(planar bed) the FEM then lifts its flat bed into the closed forms' "
      "floor, and a number that differs from that rise by more than "
      "1 % of it is refused unless Floor lift against bedding = may "
      "differ. The y of Eq. 6.51 is not this input: it follows from the "
      "bedding shape (closed forms) or from the computed block rotations "
      "(FEM). Units: m.");
    prm.declare_entry(
      "Floor lift against bedding",
      "must match",
      Selection("must match|may differ"),
      "must match: a numeric Floor lift that differs from the bedding's "
      "rise (see Floor lift) by more than 1 % of it is refused, because the "
      "FEM would lift a different floor than the closed forms stand on. "
      "may differ: the FEM lifts by Floor lift whatever the bedding; the "
      "terminal and report.md say that the two models see different "
      "floors. Units: none.");
    prm.declare_entry("Uplift mode",
                      "parabola",
                      Selection("vertical|dip toward face|dip away from face|"
                                "tilt|parabola|slope"),
                      "How the base moves in the floor-uplift stage while "
                      "the face block stays fixed: straight up; along the "
                      "bedding chord under the blocks toward or away from "
                      "the face; tilted about its free end so the face end "
                      "rises; bent into u_y = lift (x/nL)^2 with x from "
                      "the face; or raised into the planar slope u_y = lift "
                      "x/nL (the planar counterpart of parabola, Figure 6.5). "
                      "Units: none.");
    prm.declare_entry(
      "Footprint length",
      "0",
      Double(0, largest_footprint),
      "3D scenes (Geometry/Dimension = 3): the support's extent along the "
      "face, the shield width b its whole Support load acts on. The load "
      "is the 2D support pressure times Geometry/Support width / Footprint "
      "length on the loaded blocks' tops within the footprint only, so its "
      "total is Support load (with Footprint length = Support width the "
      "pressure is the 2D one). 0: no footprint; the 2D load per metre of "
      "face (Support load over Support width) acts along the whole Face "
      "length, as under a row of supports side by side. Must not exceed "
      "Geometry/Face length; must be 0 in 2D. Units: m.");
    prm.declare_entry(
      "Footprint offset",
      "-1",
      Double(centred_offset, largest_footprint),
      "3D scenes with Footprint length > 0: z of the footprint's start "
      "along the face (the face runs from z = 0 to Geometry/Face length), "
      "between 0 and Face length - Footprint length. -1 (the default): "
      "centred on the face. Any other value below 0 is refused, and so is "
      "an offset without a footprint. Units: m.");
    prm.leave_subsection();
  }

  void
  LoadingParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    gravity = prm.get_double("Gravity");
    support_load =
      Units::tonnes_force_to_newtons(prm.get_double("Support load"));
    const std::string loaded = prm.get("Loaded blocks from face");
    support_load_direction   = prm.get("Support load direction") == "vertical" ?
                                 SupportLoadDirection::vertical :
                                 SupportLoadDirection::top_normal;
    const std::string lift   = prm.get("Floor lift");
    floor_lift_auto          = is_auto(lift);
    floor_lift = floor_lift_auto ? 0. : prm.get_double("Floor lift");
    floor_lift_may_differ =
      prm.get("Floor lift against bedding") == "may differ";
    const std::string mode = prm.get("Uplift mode");
    uplift_mode            = mode == "vertical"        ? UpliftMode::vertical :
                             mode == "dip toward face" ? UpliftMode::dip_toward_face :
                             mode == "dip away from face" ?
                                                         UpliftMode::dip_away_from_face :
                             mode == "tilt"  ? UpliftMode::tilt :
                             mode == "slope" ? UpliftMode::slope :
                                               UpliftMode::parabola;
    footprint_length       = prm.get_double("Footprint length");
    const double offset    = prm.get_double("Footprint offset");
    prm.leave_subsection();

    if (offset == centred_offset)
      footprint_offset.reset();
    else if (offset < 0.)
      throw InputError("Loading/Footprint offset",
                       std::to_string(offset),
                       "must be -1 (centred on the face) or between 0 and "
                       "Geometry/Face length - Loading/Footprint length (m)");
    else
      footprint_offset = offset;

    loaded_blocks_from_face.clear();
    std::set<unsigned int> seen;
    for (const std::string &entry :
         dealii::Utilities::split_string_list(loaded, ','))
      {
        const unsigned int block = dealii::Utilities::string_to_int(entry);
        if (!seen.insert(block).second)
          throw InputError("Loading/Loaded blocks from face",
                           loaded,
                           "each block may appear only once");
        loaded_blocks_from_face.push_back(block);
      }
  }
} // namespace FloorBlock::Parameters
