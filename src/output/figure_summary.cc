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
      double Contact::JointReport::*member; ///< the figure, SI
      FigureError JointErrors::*error;      ///< its estimated error
      const char *name;  ///< shown to the user
      const char *unit;  ///< SI unit of the stored value
      double      scale; ///< SI -> shown unit
      const char *shown_unit;
    };

    constexpr std::array<Figure, 4> figures = {
      {{"normal_force_N_per_m", &Contact::JointReport::normal_force,
        &JointErrors::normal_force, "Q", "N/m",
        1. / Units::newtons_per_kilonewton, "kN/m"},
       {"contact_length_m", &Contact::JointReport::closed_length,
        &JointErrors::contact_length, "contact length", "m", 1e3, "mm"},
       {"sigma_max_Pa", &Contact::JointReport::peak_normal_stress,
        &JointErrors::sigma_max, "sigma_max", "Pa",
        1. / Units::pascals_per_megapascal, "MPa"},
       {"sigma_max_averaged_Pa",
        &Contact::JointReport::averaged_peak_normal_stress,
        &JointErrors::sigma_max_averaged, "sigma_max averaged", "Pa",
        1. / Units::pascals_per_megapascal, "MPa"}}};

    double
    solve_time(const Contact::SolveResult &result)
    {
      double total = 0.;
      for (const auto &[section, seconds] : result.wall_times)
        total += seconds;
      return total;
    }
  } // namespace

  json
  face_joint_figures(const Contact::SolveResult              &solve,
                     const std::optional<FemErrorEstimate> &error_estimate,
                     const unsigned int                     n_blocks)
  {
    const std::string           face  = "vertical " + std::to_string(n_blocks);
    const Contact::JointReport *joint = nullptr;
    if (!solve.increments.empty())
      for (const auto &candidate : solve.increments.back().joints)
        if (candidate.name == face)
          joint = &candidate;
    const bool estimated = error_estimate && error_estimate->available;
    json result = json::array();
    if (joint == nullptr)
      return result;
    for (const Figure &figure : figures)
      {
        json error = nullptr;
        if (estimated && error_estimate->joints.count(face) > 0)
          {
            const auto &relative =
              (error_estimate->joints.at(face).*figure.error).relative_error;
            if (relative)
              error = *relative;
          }
        result.push_back(
          {{"quantity", figure.name},
           {"field", figure.key},
           {"value", joint->*figure.member},
           {"unit", figure.unit},
           {"relative_error", error},
           // A null error always comes with a status that says why.
           {"status", error.is_number() ? "estimated" : "error not estimated"},
           {"error_method",
            estimated ? json(error_estimate->method) :
                        json("none: no error estimate was made or it failed")},
           {"wall_time_s", solve_time(solve)}});
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

  std::string
  figure_lines(const Contact::SolveResult              &solve,
               const std::optional<FemErrorEstimate> &error_estimate,
               const unsigned int                     n_blocks)
  {
    return figure_lines(face_joint_figures(solve, error_estimate, n_blocks));
  }
} // namespace FloorBlock::Output
