#include <common/units.h>
#include <output/figure_summary.h>

#include <fmt/format.h>

#include <array>

namespace FloorBlock::Output
{
  using nlohmann::json;

  namespace
  {
    struct Figure
    {
      const char *key;   ///< field in fem.json and in the error estimate
      const char *name;  ///< shown to the user
      const char *unit;  ///< SI unit of the stored value
      double      scale; ///< SI -> shown unit
      const char *shown_unit;
    };

    constexpr std::array<Figure, 4> figures = {
      {{"normal_force_N_per_m", "Q", "N/m", 1. / Units::newtons_per_kilonewton,
        "kN/m"},
       {"contact_length_m", "contact length", "m", 1e3, "mm"},
       {"sigma_max_Pa", "sigma_max", "Pa", 1. / Units::pascals_per_megapascal,
        "MPa"},
       {"sigma_max_averaged_Pa", "sigma_max averaged", "Pa",
        1. / Units::pascals_per_megapascal, "MPa"}}};

    double
    solve_time(const json &fem)
    {
      double total = 0.;
      if (fem.contains("wall_time_s") && fem["wall_time_s"].is_object())
        for (const auto &[section, seconds] : fem["wall_time_s"].items())
          total += seconds.get<double>();
      return total;
    }
  } // namespace

  json
  face_joint_figures(const json        &fem,
                     const json        &error_estimate,
                     const unsigned int n_blocks)
  {
    const std::string face = "vertical " + std::to_string(n_blocks);
    json joint;
    for (const auto &candidate : fem["joints"])
      if (candidate["name"] == face)
        joint = candidate;
    const bool estimated = error_estimate.is_object() &&
                           error_estimate.value("status", "") == "available";
    json result = json::array();
    if (joint.is_null())
      return result;
    for (const Figure &figure : figures)
      {
        json error = nullptr;
        if (estimated)
          {
            const json &joints = error_estimate["joints"];
            if (joints.contains(face) && joints[face].contains(figure.key))
              error = joints[face][figure.key]["relative_error"];
          }
        result.push_back(
          {{"quantity", figure.name},
           {"field", figure.key},
           {"value", joint[figure.key]},
           {"unit", figure.unit},
           {"relative_error", error},
           // A null error always comes with a status that says why.
           {"status", error.is_number() ? "estimated" : "error not estimated"},
           {"error_method",
            estimated ? error_estimate["method"] :
                        json("none: no error estimate was made or it failed")},
           {"wall_time_s", solve_time(fem)}});
      }
    return result;
  }

  std::string
  figure_lines(const json &figures)
  {
    std::string text;
    for (const auto &entry : figures)
      for (const Figure &figure : Output::figures)
        if (entry["field"] == figure.key)
          text += fmt::format(
            "  {} = {:.4g} {} {} in {:.1f} s\n",
            figure.name, entry["value"].get<double>() * figure.scale,
            figure.shown_unit,
            entry["relative_error"].is_number() ?
              fmt::format("+- {:.2g} %",
                          100. * entry["relative_error"].get<double>()) :
              std::string("(error not estimated)"),
            entry["wall_time_s"].get<double>());
    return text;
  }
} // namespace FloorBlock::Output
