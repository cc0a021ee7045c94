#include <common/input_error.h>
#include <parameters/auto_or_double.h>
#include <parameters/sections.h>
#include <parameters/value_text.h>
#include <strength/critical_distance.h>


namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;

  void
  StrengthParameters::declare_parameters(ParameterHandler &prm)
  {
    // Defaults: a siltstone floor of a coal-measure sequence, the rock the
    // chapter's floor blocks stand for.
    prm.enter_subsection("Strength");
    prm.declare_entry(
      "Intact UCS",
      "40e6",
      Double(1e5, 5e8),
      "sigma_ci, uniaxial compressive strength of the intact rock. Default: "
      "a coal-measure siltstone (assumed; mudstones 10-40 MPa, siltstones "
      "30-80 MPa). Units: Pa.");
    prm.declare_entry(
      "m_i",
      "7",
      Double(1, 50),
      "Hoek-Brown constant of the intact rock (Hoek, Practical Rock "
      "Engineering, 2007, Table 11.2: siltstone 7 +- 2, mudstone 4 +- 2, "
      "claystone 4 +- 2, sandstone 17 +- 4). Units: none.");
    prm.declare_entry(
      "GSI",
      "75",
      Double(10, 100),
      "Geological Strength Index of the rock between the modelled joints. "
      "The scene meshes the vertical joints and the bedding, so what is "
      "left are the floor strata's laminae and minor fractures (assumed: "
      "75, a blocky mass of good surfaces; a jointed mass whose joints are "
      "not modelled would be 40-60). 100: intact rock. Units: none.");
    prm.declare_entry(
      "Disturbance",
      "0",
      Double(0, 1),
      "Hoek-Brown disturbance factor D (Hoek, Carranza-Torres and Corkum "
      "2002): 0 for a floor cut by the shearer, not blasted; up to 1 for "
      "heavy blast damage. Units: none.");
    prm.declare_entry(
      "Tensile strength",
      "auto",
      AutoOrDouble(1e3, 1e8),
      "sigma_t of the intact rock, for the critical distance; must be below "
      "Intact UCS. auto: the intact Hoek-Brown value sigma_ci / m_i "
      "(5.7 MPa for the defaults). The strength factor's own tensile limit "
      "is the rock mass's s sigma_ci / m_b. Units: Pa.");
    prm.declare_entry(
      "Fracture toughness",
      "1e6",
      Double(1e4, 1e7),
      "K_Ic, mode I fracture toughness of the intact rock (assumed: 1 MPa "
      "m^0.5; siltstones and mudstones measure about 0.5-1.5 MPa m^0.5). "
      "Units: Pa m^0.5.");
    prm.declare_entry(
      "Critical distance",
      "auto",
      AutoOrDouble(1e-5, 1.),
      "L of the theory of critical distances (Taylor 2007): the point "
      "method reads the stress at L/2 from a corner, the line method "
      "averages it over L along the corner's bisector, the area method "
      "over the block within L of the corner. auto: L = (K_Ic / sigma_t)^2 "
      "/ pi (9.7 mm for the defaults). In a 2D elastic solve below the "
      "smallest block side less the corner rounding radius. Units: m.");
    prm.leave_subsection();
  }

  void
  StrengthParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Strength");
    intact_ucs         = prm.get_double("Intact UCS");
    m_i                = prm.get_double("m_i");
    gsi                = prm.get_double("GSI");
    disturbance        = prm.get_double("Disturbance");
    fracture_toughness = prm.get_double("Fracture toughness");
    const std::string tension = prm.get("Tensile strength");
    tensile_strength =
      is_auto(tension) ? intact_ucs / m_i : prm.get_double("Tensile strength");
    const std::string distance = prm.get("Critical distance");
    critical_distance =
      is_auto(distance) ?
        Strength::critical_distance(fracture_toughness, tensile_strength) :
        prm.get_double("Critical distance");
    prm.leave_subsection();

    if (!(tensile_strength < intact_ucs))
      throw InputError("Strength/Tensile strength",
                       pascals(tensile_strength),
                       "must be below Strength/Intact UCS = " +
                         pascals(intact_ucs) +
                         (is_auto(tension) ? " (auto: sigma_ci / m_i)" : ""));
    // An auto L outside the range a given one must meet.
    if (!(critical_distance >= 1e-5 && critical_distance <= 1.))
      throw InputError("Strength/Critical distance",
                       "auto = " + std::to_string(critical_distance) + " m",
                       "must lie between 1e-5 and 1 m: (K_Ic / sigma_t)^2 / "
                       "pi from Strength/Fracture toughness and Tensile "
                       "strength; give L, or K_Ic and sigma_t that fit");
  }

  Strength::HoekBrownConstants
  StrengthParameters::hoek_brown() const
  {
    return Strength::generalised_hoek_brown(m_i, gsi, disturbance);
  }
} // namespace FloorBlock::Parameters
