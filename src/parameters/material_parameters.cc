#include <common/input_error.h>
#include <parameters/auto_or_double.h>
#include <parameters/sections.h>
#include <parameters/value_text.h>

#include <cmath>
#include <sstream>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Double;

  namespace
  {
    // Bounds of the moduli (Pa): softer than 1 MPa or stiffer than 10 TPa
    // is no rock and most likely a unit slip (GPa or MPa written as Pa).
    constexpr double softest_modulus  = 1.0e6;
    constexpr double stiffest_modulus = 1.0e13;
    // Chapter Table 6.1, taken when neither pair is given.
    constexpr double table_bulk_modulus  = 9.0e9;
    constexpr double table_shear_modulus = 6.7e9;

    /** A modulus derived from the other pair, within the declared bounds. */
    double
    bounded_modulus(const double value, const std::string &name)
    {
      if (!(value >= softest_modulus && value <= stiffest_modulus))
        throw InputError("Material/Young's modulus and Poisson's ratio",
                         name + " " + pascals(value),
                         "must give a " + name +
                           " between 1e6 and 1e13 Pa, as Bulk and Shear "
                           "modulus allow");
      return value;
    }
  } // namespace

  void
  MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry(
      "Bulk modulus",
      "auto",
      AutoOrDouble(softest_modulus, stiffest_modulus),
      "Bulk modulus K of the intact rock. Give either Bulk modulus and "
      "Shear modulus or Young's modulus and Poisson's ratio; the other "
      "pair stays auto and is derived (echoed in parameters.prm). All four "
      "auto: the chapter's Table 6.1, K = 9 GPa and G = 6.7 GPa. Units: Pa.");
    prm.declare_entry(
      "Shear modulus",
      "auto",
      AutoOrDouble(softest_modulus, stiffest_modulus),
      "Shear modulus G of the intact rock; auto: see Bulk modulus (chapter "
      "Table 6.1: 6.7 GPa). Units: Pa.");
    prm.declare_entry(
      "Young's modulus",
      "auto",
      AutoOrDouble(softest_modulus, stiffest_modulus),
      "Young's modulus E of the intact rock, as a site report gives it, "
      "together with Poisson's ratio instead of Bulk and Shear modulus; "
      "auto: derived from them, E = 9KG/(3K+G). Units: Pa.");
    prm.declare_entry(
      "Poisson's ratio",
      "auto",
      AutoOrDouble(-1, 0.5),
      "Poisson's ratio nu of the intact rock, together with Young's "
      "modulus; must lie strictly between -1 and 0.5. auto: derived from "
      "Bulk and Shear modulus, nu = (3K-2G)/(2(3K+G)). Units: none.");
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
    const std::string names[4] = {"Bulk modulus",
                                  "Shear modulus",
                                  "Young's modulus",
                                  "Poisson's ratio"};
    std::string       values[4];
    bool              given[4];
    for (unsigned int entry = 0; entry < 4; ++entry)
      {
        values[entry] = prm.get(names[entry]);
        given[entry]  = !is_auto(values[entry]);
      }
    const auto number = [&](const unsigned int entry) {
      return prm.get_double(names[entry]);
    };
    const bool bulk_shear     = given[0] || given[1];
    const bool youngs_poisson = given[2] || given[3];
    derived_text.clear();

    if (bulk_shear && youngs_poisson)
      {
        std::string written;
        for (unsigned int entry = 0; entry < 4; ++entry)
          if (given[entry])
            written += (written.empty() ? "" : ", ") + names[entry] + " = " +
                       values[entry];
        throw InputError(
          "Material/" + std::string(given[0] ? names[0] : names[1]) +
          " and Material/" + (given[2] ? names[2] : names[3]) + ": " + written +
          ": give either Bulk modulus and Shear modulus or "
          "Young's modulus and Poisson's ratio, and set the other pair to "
          "auto (it is derived)");
      }
    for (const unsigned int first : {0u, 2u})
      if (given[first] != given[first + 1])
        {
          const unsigned int missing = given[first] ? first + 1 : first;
          const unsigned int present = given[first] ? first : first + 1;
          throw InputError("Material/" + names[missing],
                           "auto",
                           "must be given together with Material/" +
                             names[present] + " = " + values[present] +
                             " (one pair of moduli describes the rock)");
        }

    if (youngs_poisson)
      {
        const double youngs  = number(2);
        const double poisson = number(3);
        if (!(poisson > -1. && poisson < 0.5))
          throw InputError("Material/Poisson's ratio",
                           values[3],
                           "must lie strictly between -1 and 0.5 (at the "
                           "bounds K or G is infinite)");
        bulk_modulus =
          bounded_modulus(youngs / (3. * (1. - 2. * poisson)), "bulk modulus");
        shear_modulus =
          bounded_modulus(youngs / (2. * (1. + poisson)), "shear modulus");
      }
    else
      {
        bulk_modulus  = bulk_shear ? number(0) : table_bulk_modulus;
        shear_modulus = bulk_shear ? number(1) : table_shear_modulus;
      }
    density = prm.get_double("Density");
    prm.leave_subsection();

    const std::string source = youngs_poisson ? "derived from E and nu" :
                               bulk_shear     ? "derived from K and G" :
                                                "Table 6.1";
    if (!bulk_shear)
      {
        derived_text.push_back(
          {names[0], source + ": " + pascals(bulk_modulus)});
        derived_text.push_back(
          {names[1], source + ": " + pascals(shear_modulus)});
      }
    if (!youngs_poisson)
      {
        std::ostringstream ratio;
        ratio.precision(6);
        ratio << poissons_ratio();
        derived_text.push_back(
          {names[2],
           (bulk_shear ? source : "from Table 6.1's K and G") + ": " +
             pascals(youngs_modulus())});
        derived_text.push_back(
          {names[3],
           (bulk_shear ? source : "from Table 6.1's K and G") + ": " +
             ratio.str()});
      }
    // With K > 0 and G > 0 (guaranteed above) nu lies in (-1, 0.5) and
    // E > 0: no further check is needed.
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
