#include <common/units.h>
#include <output/comparison_report.h>
#include <output/fem_report.h>

#include <fmt/format.h>

#include <cmath>

namespace FloorBlock::Output
{
  using nlohmann::json;

  namespace
  {
    constexpr double kN  = Units::newtons_per_kilonewton;
    constexpr double MPa = Units::pascals_per_megapascal;

    /// (fem - reference)/reference, or null where it is undefined.
    json
    relative_difference(const double fem, const double reference)
    {
      if (reference == 0. || !std::isfinite(reference))
        return nullptr;
      return (fem - reference) / std::abs(reference);
    }

    json
    contact_json(const Compare::JointComparison & joint,
                 const Compare::ContactConstants &constants)
    {
      const auto &contact = joint.contact;
      const auto &formula = contact.closed_form;
      const bool  defined = formula.status == Analytic::Status::ok ||
                           formula.status ==
                             Analytic::Status::contact_longer_than_block;
      const auto  value   = [&](const double x) -> json {
        return defined ? json(x) : json(nullptr);
      };
      return {
        {"status", Analytic::to_string(formula.status)},
        {"status_text", Analytic::describe(formula.status)},
        {"Q_contact_N", contact.force_over_width},
        {"relative_rotation_rad", contact.relative_rotation},
        {"y_m", contact.floor_lift},
        {"E_Pa", constants.youngs_modulus},
        {"b_m", constants.support_width},
        {"L_m", constants.block_width},
        {"H_m", constants.block_height},
        {"A_6_51_m2", value(formula.contact_area)},
        {"A_fem_m2", contact.fem_area},
        {"A_relative_difference",
         defined ? relative_difference(contact.fem_area, formula.contact_area) :
                   json(nullptr)},
        {"sigma_avg_6_52_Pa", value(formula.average_stress)},
        {"sigma_mean_fem_Pa", contact.fem_mean_stress},
        {"sigma_avg_relative_difference",
         defined ? relative_difference(contact.fem_mean_stress,
                                       formula.average_stress) :
                   json(nullptr)},
        {"sigma_max_6_53_Pa", value(formula.max_stress)},
        {"sigma_max_fem_Pa", contact.fem_peak_stress},
        {"sigma_max_averaged_fem_Pa", contact.fem_averaged_peak_stress},
        {"sigma_max_averaged_relative_difference",
         defined ? relative_difference(contact.fem_averaged_peak_stress,
                                       formula.max_stress) :
                   json(nullptr)}};
    }

    std::string
    over_or_under(const double relative, const std::string &what,
                  const std::string &equation)
    {
      const double percent = 100. * std::abs(relative);
      if (percent < 0.5)
        return fmt::format("{} matches the FEM {} at the face joint "
                           "(within 0.5 %)",
                           equation, what);
      // relative = (FEM - formula)/formula: FEM above means the formula is low.
      return fmt::format("{} {} the {} by {:.0f} % at the face joint",
                         equation,
                         relative > 0 ? "underestimates" : "overestimates",
                         what, percent);
    }
  } // namespace

  json
  comparison_json(const std::vector<Compare::JointComparison> &joints,
                  const Compare::ContactConstants &            constants,
                  const unsigned int                           n_blocks)
  {
    json records = json::array();
    for (const auto &joint : joints)
      {
        json forces = json::object();
        for (const auto &force : joint.forces)
          forces[force.mechanism] = {
            {"status", force.status},
            {"Q_N_per_m", force.has_value ? json(force.closed_form) :
                                            json(nullptr)},
            {"relative_difference",
             force.has_value ?
               relative_difference(joint.fem_force, force.closed_form) :
               json(nullptr)}};
        records.push_back(
          {{"joint", joint.joint},
           {"blocks", joint_bodies("vertical", joint.joint, n_blocks)},
           {"Q_fem_N_per_m", joint.fem_force},
           {"Q_closed_form", forces},
           {"contact", contact_json(joint, constants)}});
      }
    return records;
  }

  json
  lift_history_entry(const Compare::JointComparison & face_joint,
                     const Compare::ContactConstants &constants,
                     const double                     base_lift)
  {
    return {{"base_lift_m", base_lift},
            {"Q_fem_N_per_m", face_joint.fem_force},
            {"contact", contact_json(face_joint, constants)}};
  }

  std::vector<std::string>
  verdicts(const Compare::JointComparison &face_joint)
  {
    std::vector<std::string> lines;
    for (const auto &force : face_joint.forces)
      lines.push_back(
        force.has_value ?
          over_or_under((face_joint.fem_force - force.closed_form) /
                          std::abs(force.closed_form),
                        "lateral force Q", force.mechanism) +
            (force.status == "ok" ? "" :
                                    " (the mechanism itself is flagged " +
                                      force.status + ")") :
          force.mechanism + " has no finite Q (" + force.status + ")");

    const auto &contact = face_joint.contact;
    const auto &formula = contact.closed_form;
    if (formula.status != Analytic::Status::ok &&
        formula.status != Analytic::Status::contact_longer_than_block)
      {
        lines.push_back("Eqs. 6.51-6.53 have no answer at the face joint: " +
                        Analytic::describe(formula.status));
        return lines;
      }
    lines.push_back(over_or_under(
      (contact.fem_area - formula.contact_area) / formula.contact_area,
      "contact area", "Eq. 6.51"));
    lines.push_back(over_or_under((contact.fem_mean_stress -
                                   formula.average_stress) /
                                    formula.average_stress,
                                  "mean contact stress", "Eq. 6.52"));
    lines.push_back(over_or_under((contact.fem_averaged_peak_stress -
                                   formula.max_stress) /
                                    formula.max_stress,
                                  "averaged peak stress", "Eq. 6.53"));
    return lines;
  }

  std::string
  force_per_joint_plot(const std::vector<Compare::JointComparison> &joints)
  {
    std::string data = "$fem << EOD\n";
    for (const auto &joint : joints)
      data += fmt::format("{} {}\n", joint.joint, joint.fem_force / kN);
    data += "EOD\n";
    std::string plot =
      "plot $fem with points pt 7 ps 1.5 lc rgb 'black' title 'FEM'";
    for (std::size_t m = 0; m < joints.front().forces.size(); ++m)
      {
        std::string rows;
        for (const auto &joint : joints)
          if (joint.forces[m].has_value)
            rows += fmt::format("{} {}\n", joint.joint,
                                joint.forces[m].closed_form / kN);
        if (rows.empty())
          continue;
        data += fmt::format("$m{} << EOD\n{}EOD\n", m, rows);
        plot += fmt::format(", $m{} with linespoints title '{}'", m,
                            joints.front().forces[m].mechanism);
      }
    return data +
           "set grid\nset key top left\nset xlabel 'vertical joint j "
           "(n = face joint)'\nset ylabel 'Q_j (kN per m of face)'\n"
           "set title 'Lateral force per joint: FEM against the closed "
           "forms'\nset xtics 1\n" +
           plot + "\n";
  }

  std::string
  lift_history_plot(const json &lift_history)
  {
    std::string data = "$h << EOD\n";
    for (const auto &entry : lift_history)
      {
        const auto &contact = entry["contact"];
        const auto  cell    = [](const json &value, const double scale) {
          return value.is_number() ? fmt::format("{}", value.get<double>() * scale) :
                                     std::string("NaN");
        };
        data += fmt::format(
          "{} {} {} {} {}\n", entry["base_lift_m"].get<double>() * 1e3,
          cell(contact["A_fem_m2"], 1.), cell(contact["A_6_51_m2"], 1.),
          cell(contact["sigma_max_averaged_fem_Pa"], 1. / MPa),
          cell(contact["sigma_max_6_53_Pa"], 1. / MPa));
      }
    data += "EOD\n";
    return data +
           "set multiplot layout 1,2 title 'Face joint along the floor "
           "lift'\nset grid\nset key top left\nset xlabel 'base lift (mm)'\n"
           "set ylabel 'contact area over b (m^2)'\n"
           "plot $h using 1:2 with linespoints title 'FEM', $h using 1:3 "
           "with linespoints title 'Eq. 6.51'\n"
           "set ylabel 'sigma_max (MPa)'\n"
           "plot $h using 1:4 with linespoints title 'FEM (averaged peak)', "
           "$h using 1:5 with linespoints title 'Eq. 6.53'\n"
           "unset multiplot\n";
  }

  std::string
  traction_profile_plot(const Contact::JointReport &face_joint)
  {
    std::string data = "$p << EOD\n";
    for (const auto &sample : face_joint.profile)
      data += fmt::format("{} {}\n", sample.position[1],
                          sample.normal_traction / MPa);
    data += "EOD\n";
    return data +
           "set grid\nunset key\nset xlabel 'normal traction (MPa)'\n"
           "set ylabel 'height y (m)'\nset title 'Normal traction along "
           "the face joint at the final lift'\n"
           "plot $p using 2:1 with linespoints pt 7 ps 0.6\n";
  }
} // namespace FloorBlock::Output
