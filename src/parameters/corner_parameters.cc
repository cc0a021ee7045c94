#include <common/input_error.h>
#include <parameters/sections.h>

#include <deal.II/base/utilities.h>

#include <algorithm>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;

  void
  CornerParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Corner");
    prm.declare_entry(
      "Joint",
      "0",
      Integer(0, 1000),
      "Vertical joint whose floor-level (top) corner `floorblock corner` "
      "analyses, chapter numbering (1 = between blocks 1 and 2, n = "
      "between block n and the face block); 0 = the face joint n. Units: "
      "none.");
    prm.declare_entry(
      "Zoom levels",
      "16",
      Integer(2, 24),
      "Most zoom levels after the scene's mesh: level k asks for cells of "
      "Mesh/Corner size / 2^k (after the scene's global refinements) "
      "around the corner's contact end and peak. The zoom stops earlier "
      "when the peak and the corner intensity K1 have converged (Corner/"
      "Converged change, Intensity change), or before cells would fall "
      "below 3e-7 of the smaller block side, where round-off takes over. "
      "Units: none.");
    prm.declare_entry(
      "Converged change",
      "0.01",
      Double(1e-4, 0.1),
      "Relative change between successive zoom levels at or below which "
      "the pointwise peak counts as converged (twice in a row); also the "
      "tolerance of the converged distance range of the traction (the "
      "level against the one before), over which the exponent is fitted. "
      "Units: none (1 = 100 %).");
    prm.declare_entry(
      "Intensity change",
      "0.02",
      Double(1e-4, 0.5),
      "Relative change of the corner intensity K1 between the last two "
      "zoom levels at or below which it counts as converged; the zoom stops when the peak and K1 have converged "
      "and the fit range spans a decade. Units: none (1 = 100 %).");
    prm.declare_entry(
      "Rounding radii",
      "0.002, 0.005, 0.01, 0.02, 0.05",
      List(Double(1e-4, 1.), 0, 20),
      "Corner rounding radii of the rounding study: the scene solved once "
      "per radius (Geometry/Corner rounding radius), each zoomed until its "
      "peak converges. Empty: no rounding study. Units: m.");
    prm.declare_entry(
      "Time budget",
      "3600",
      Double(10., 1e6),
      "Wall time of the whole `corner` command: no zoom level or rounding "
      "radius is started once it is spent, and the report says which "
      "figures it cut short. Units: s.");
    prm.leave_subsection();
  }

  void
  CornerParameters::parse_parameters(ParameterHandler  &prm,
                                     const unsigned int n_blocks)
  {
    prm.enter_subsection("Corner");
    const long chosen = prm.get_integer("Joint");
    if (chosen > static_cast<long>(n_blocks))
      throw InputError("Corner/Joint",
                       std::to_string(chosen),
                       "must be 0 (the face joint) or between 1 and "
                       "Geometry/Number of blocks = " +
                         std::to_string(n_blocks));
    joint = chosen == 0 ? n_blocks : static_cast<unsigned int>(chosen);
    max_zoom_levels  = prm.get_integer("Zoom levels");
    converged_change = prm.get_double("Converged change");
    intensity_change = prm.get_double("Intensity change");
    rounding_radii.clear();
    for (const std::string &entry :
         dealii::Utilities::split_string_list(prm.get("Rounding radii")))
      rounding_radii.push_back(dealii::Utilities::string_to_double(entry));
    std::sort(rounding_radii.begin(), rounding_radii.end());
    time_budget = prm.get_double("Time budget");
    prm.leave_subsection();
  }
} // namespace FloorBlock::Parameters
