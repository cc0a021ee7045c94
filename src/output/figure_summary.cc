#include <common/units.h>
#include <compare/joint_name.h>
#include <output/figure_summary.h>

#include <fmt/format.h>

#include <array>
#include <vector>

namespace FloorBlock::Output
{
  using nlohmann::json;

  namespace
  {
    struct Figure
    {
      const char *key; ///< field in fem.json and in the error estimate
      double Contact::JointReport::*member; ///< the figure, SI
      FigureError JointErrors::*error;      ///< its estimated error
      const char               *name;       ///< shown to the user
      const char               *unit;       ///< SI unit of the stored value
      double                    scale;      ///< SI -> shown unit
      const char               *shown_unit;
    };

    constexpr std::array<Figure, 4> figures = {
      {{"normal_force_N_per_m",
        &Contact::JointReport::normal_force,
        &JointErrors::normal_force,
        "Q",
        "N/m",
        1. / Units::newtons_per_kilonewton,
        "kN/m"},
       {"contact_length_m",
        &Contact::JointReport::closed_length,
        &JointErrors::contact_length,
        "contact length",
        "m",
        1e3,
        "mm"},
       {"sigma_max_Pa",
        &Contact::JointReport::peak_normal_stress,
        &JointErrors::sigma_max,
        "sigma_max",
        "Pa",
        1. / Units::pascals_per_megapascal,
        "MPa"},
       {"sigma_max_averaged_Pa",
        &Contact::JointReport::averaged_peak_normal_stress,
        &JointErrors::sigma_max_averaged,
        "sigma_max averaged",
        "Pa",
        1. / Units::pascals_per_megapascal,
        "MPa"}}};

    double
    solve_time(const Contact::SolveResult &result)
    {
      double total = 0.;
      for (const auto &[section, seconds] : result.wall_times)
        total += seconds;
      return total;
    }

    /** One face-joint figure with its estimated relative error. */
    struct FaceFigure
    {
      const Figure         *figure;
      double                value; ///< SI, figure->unit
      std::optional<double> relative_error;
    };

    /** The face joint's figures; none when no increment has the joint. */
    std::vector<FaceFigure>
    face_figures(const Contact::SolveResult            &solve,
                 const std::optional<FemErrorEstimate> &error_estimate,
                 const unsigned int                     n_blocks)
    {
      const std::string           face  = Compare::face_joint_name(n_blocks);
      const Contact::JointReport *joint = nullptr;
      if (!solve.increments.empty())
        for (const auto &candidate : solve.increments.back().joints)
          if (candidate.name == face)
            joint = &candidate;
      std::vector<FaceFigure> result;
      if (joint == nullptr)
        return result;
      const bool estimated = error_estimate && error_estimate->available &&
                             error_estimate->joints.count(face) > 0;
      for (const Figure &figure : figures)
        result.push_back(
          {&figure,
           joint->*figure.member,
           estimated ?
             (error_estimate->joints.at(face).*figure.error).relative_error :
             std::nullopt});
      return result;
    }
  } // namespace

  json
  face_joint_figures(const Contact::SolveResult            &solve,
                     const std::optional<FemErrorEstimate> &error_estimate,
                     const unsigned int                     n_blocks)
  {
    const bool estimated = error_estimate && error_estimate->available;
    json       result    = json::array();
    for (const FaceFigure &entry :
         face_figures(solve, error_estimate, n_blocks))
      result.push_back(
        {{"quantity", entry.figure->name},
         {"field", entry.figure->key},
         {"value", entry.value},
         {"unit", entry.figure->unit},
         {"relative_error",
          entry.relative_error ? json(*entry.relative_error) : json(nullptr)},
         // A null error always comes with a status that says why.
         {"status", entry.relative_error ? "estimated" : "error not estimated"},
         {"error_method",
          estimated ? error_estimate->method :
                      "none: no error estimate was made or it failed"},
         {"wall_time_s", solve_time(solve)}});
    return result;
  }

  std::string
  figure_lines(const Contact::SolveResult            &solve,
               const std::optional<FemErrorEstimate> &error_estimate,
               const unsigned int                     n_blocks)
  {
    std::string text;
    for (const FaceFigure &entry :
         face_figures(solve, error_estimate, n_blocks))
      text +=
        fmt::format("  {} = {:.4g} {} {} in {:.1f} s\n",
                    entry.figure->name,
                    entry.value * entry.figure->scale,
                    entry.figure->shown_unit,
                    entry.relative_error ?
                      fmt::format("+- {:.2g} %", 100. * *entry.relative_error) :
                      std::string("(error not estimated)"),
                    solve_time(solve));
    return text;
  }
} // namespace FloorBlock::Output
