#include <common/units.h>
#include <output/comparison_report.h>
#include <output/fem_report.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace FloorBlock::Output
{
  using nlohmann::json;

  namespace
  {
    using Units::kN;
    using Units::MPa;

    /// (fem - reference)/reference, or null where it is undefined.
    json
    relative_difference(const double fem, const double reference)
    {
      if (reference == 0. || !std::isfinite(reference))
        return nullptr;
      return (fem - reference) / std::abs(reference);
    }

    /// Eqs. 6.51-6.53 gave a number: ok or whole_joint_in_contact.
    bool
    has_closed_form(const Analytic::CornerContact &formula)
    {
      return Analytic::has_contact_values(formula.status);
    }

    /// A closed form with a number that is exactly 0 (FEM Q = 0 here).
    bool
    has_zero_reference(const Analytic::CornerContact &formula)
    {
      return formula.contact_area == 0. || formula.average_stress == 0. ||
             formula.max_stress == 0.;
    }

    /**
     * Status of a contact record: no_load when the FEM carries none; the
     * closed form's own when it has no number; zero_closed_form when its
     * numbers are 0 (relative differences undefined); else the closed
     * form's (ok or flagged).
     */
    std::pair<std::string, std::string>
    contact_status(const Compare::JointComparison &joint)
    {
      const auto &formula = joint.contact.closed_form;
      // y comes from the FEM: without load it is round-off, and so is
      // whatever the closed form makes of it.
      if (!joint.contact.fem_carries_load)
        return {"no_load", no_load_text(joint.load)};
      if (has_closed_form(formula) && has_zero_reference(formula))
        return {"zero_closed_form",
                "Eqs. 6.51-6.53 give zero contact area and stress here (the "
                "FEM's Q at this joint is zero or negative), so the relative "
                "differences are undefined."};
      return {Analytic::to_string(formula.status),
              Analytic::describe(formula.status)};
    }

    json
    contact_json(const Compare::JointComparison  &joint,
                 const Compare::ContactConstants &constants)
    {
      const auto &contact = joint.contact;
      const auto &formula = contact.closed_form;
      const bool  defined = has_closed_form(formula);
      const bool  comparable =
        defined && contact.fem_carries_load && !has_zero_reference(formula);
      const auto value = [&](const double x) -> json {
        return defined ? json(x) : json(nullptr);
      };
      const auto difference = [&](const double fem, const double reference) {
        return comparable ? relative_difference(fem, reference) : json(nullptr);
      };
      const auto [status, status_text] = contact_status(joint);
      return {{"status", status},
              {"status_text", status_text},
              {"closed_form_status", Analytic::to_string(formula.status)},
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
               difference(contact.fem_area, formula.contact_area)},
              {"sigma_avg_6_52_Pa", value(formula.average_stress)},
              {"sigma_mean_fem_Pa", contact.fem_mean_stress},
              {"sigma_avg_relative_difference",
               difference(contact.fem_mean_stress, formula.average_stress)},
              {"sigma_max_6_53_Pa", value(formula.max_stress)},
              {"sigma_max_fem_Pa", contact.fem_peak_stress},
              {"sigma_max_averaged_fem_Pa", contact.fem_averaged_peak_stress},
              {"sigma_max_averaged_relative_difference",
               difference(contact.fem_averaged_peak_stress,
                          formula.max_stress)}};
    }

    /**
     * One closed form's Q at a joint: the record's status explains every
     * null (the closed form has no answer, the FEM carries no load, or the
     * closed form is exactly 0); closed_form_status is always the closed
     * form's own.
     */
    json
    force_json(const Compare::ForceComparison &force,
               const Compare::JointComparison &joint)
    {
      using Compare::DifferenceStatus;
      std::string status      = force.status;
      std::string status_text = Analytic::describe(force.closed_form_status);
      if (force.difference_status == DifferenceStatus::no_load)
        {
          status      = Compare::to_string(force.difference_status);
          status_text = no_load_text(joint.load);
        }
      else if (force.difference_status == DifferenceStatus::other_scene)
        {
          status      = Compare::to_string(force.difference_status);
          status_text = "The closed forms describe another scene than the "
                        "FEM's (closed_form_inputs.scene_differences), so "
                        "no relative difference is given.";
        }
      else if (force.difference_status == DifferenceStatus::zero_closed_form)
        {
          status      = Compare::to_string(force.difference_status);
          status_text = "The closed form gives Q = 0 here, so the relative "
                        "difference is undefined; difference_N_per_m is the "
                        "FEM's Q minus the closed form's.";
        }
      const bool defined = force.difference_status == DifferenceStatus::defined;
      const bool other_scene =
        force.difference_status == DifferenceStatus::other_scene;
      return {{"status", status},
              {"status_text", status_text},
              {"closed_form_status", force.status},
              {"Q_N_per_m",
               force.has_value ? json(force.closed_form) : json(nullptr)},
              {"difference_N_per_m",
               force.has_value && !other_scene ?
                 json(joint.fem_force - force.closed_form) :
                 json(nullptr)},
              {"relative_difference",
               defined ? json(force.relative_difference) : json(nullptr)}};
    }

    std::string
    over_or_under(const double       relative,
                  const std::string &what,
                  const std::string &equation)
    {
      const double percent = 100. * std::abs(relative);
      if (percent < 0.5)
        return fmt::format("{} matches the FEM {} at the face joint "
                           "(within 0.5 %)",
                           equation,
                           what);
      // relative = (FEM - formula)/formula: FEM above means the formula is low.
      return fmt::format("{} {} the {} by {:.0f} % at the face joint",
                         equation,
                         relative > 0 ? "underestimates" : "overestimates",
                         what,
                         percent);
    }
  } // namespace

  json
  comparison_json(const std::vector<Compare::JointComparison> &joints,
                  const Compare::ContactConstants             &constants,
                  const unsigned int                           n_blocks)
  {
    json records = json::array();
    for (const auto &joint : joints)
      {
        json forces = json::object();
        for (const auto &force : joint.forces)
          forces[force.mechanism] = force_json(force, joint);
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
  lift_history_entry(const Compare::JointComparison  &face_joint,
                     const Compare::ContactConstants &constants,
                     const double                     base_lift)
  {
    return {{"base_lift_m", base_lift},
            {"Q_fem_N_per_m", face_joint.fem_force},
            {"contact", contact_json(face_joint, constants)}};
  }

  std::string
  force_table_markdown(const std::vector<Compare::JointComparison> &joints,
                       const unsigned int                           n_blocks)
  {
    // Mechanisms in name order, as in summary.json's Q_closed_form.
    const auto by_name = [](const Compare::JointComparison &joint) {
      std::map<std::string, const Compare::ForceComparison *> forces;
      for (const auto &force : joint.forces)
        forces[force.mechanism] = &force;
      return forces;
    };
    std::string text = "| joint | blocks | FEM Q (kN/m) |";
    std::string rule = "|---|---|---|";
    for (const auto &[mechanism, force] : by_name(joints.front()))
      {
        text += " " + mechanism + " (kN/m, FEM vs it) |";
        rule += "---|";
      }
    text += "\n" + rule + "\n";
    for (const auto &joint : joints)
      {
        text +=
          fmt::format("| {} | {} | {:.1f} |",
                      joint.joint,
                      joint_bodies("vertical", joint.joint, n_blocks).dump(),
                      joint.fem_force / kN);
        for (const auto &[mechanism, force] : by_name(joint))
          text += fmt::format(
            " {} ({}) |",
            force->has_value ?
              fmt::format("{:.1f}", force->closed_form * (1 / kN)) :
              std::string("-"),
            force->difference_status == Compare::DifferenceStatus::defined ?
              fmt::format("{:+.0f} %", 100. * force->relative_difference) :
              std::string("-"));
        text += "\n";
      }
    return text;
  }

  std::string
  contact_table_markdown(const std::vector<Compare::JointComparison> &joints)
  {
    std::string text =
      "| joint | y (mm) | A FEM (m^2) | A 6.51 (m^2) | sigma_mean FEM "
      "(MPa) | sigma_avg 6.52 (MPa) | sigma_max FEM averaged / pointwise "
      "(MPa) | sigma_max 6.53 (MPa) | status |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto &joint : joints)
      {
        const auto &contact = joint.contact;
        const auto &formula = contact.closed_form;
        const bool  defined = has_closed_form(formula);
        const auto  closed = [defined](const double value, const double scale) {
          return defined ? fmt::format("{:.4f}", value * scale) :
                            std::string("-");
        };
        const auto closed_stress = [defined](const double value) {
          return defined ? fmt::format("{:.2f}", value * (1 / MPa)) :
                           std::string("-");
        };
        text += fmt::format(
          "| {} | {:.3f} | {:.4f} | {} | {:.2f} | {} | {:.2f} / {:.2f} | {} "
          "| {} |\n",
          joint.joint,
          contact.floor_lift * 1e3,
          contact.fem_area * 1.,
          closed(formula.contact_area, 1.),
          contact.fem_mean_stress * (1 / MPa),
          closed_stress(formula.average_stress),
          contact.fem_averaged_peak_stress * (1 / MPa),
          contact.fem_peak_stress * (1 / MPa),
          closed_stress(formula.max_stress),
          contact_status(joint).first);
      }
    return text;
  }

  namespace
  {
    /**
     * "v unit" when every value is the same (relative 1e-12), else the
     * values in order, "v1, v2, ... unit".
     */
    std::string
    values_text(const std::vector<double> &values,
                const double               scale,
                const std::string         &unit)
    {
      bool same = true;
      for (const double value : values)
        same = same && std::abs(value - values.front()) <=
                         1e-12 * std::abs(values.front());
      std::vector<std::string> texts;
      for (const double value : values)
        texts.push_back(fmt::format("{:.4g}", value * scale));
      return same ? texts.front() + " " + unit :
                    fmt::format("{} {}", fmt::join(texts, ", "), unit);
    }
  } // namespace

  std::vector<std::string>
  closed_form_input_lines(const Compare::ClosedFormInputs &inputs)
  {
    std::vector<double>      loads;
    std::vector<std::size_t> loaded;
    for (std::size_t i = 0; i < inputs.support_load.size(); ++i)
      if (inputs.support_load[i] > 0.)
        {
          loads.push_back(inputs.support_load[i]);
          loaded.push_back(i + 1);
        }
    const std::string support =
      loads.empty() ? std::string("0") :
                      fmt::format("{} vertical on block{} {}",
                                  values_text(loads, 1. / kN, "kN/m"),
                                  loaded.size() > 1 ? "s" : "",
                                  fmt::join(loaded, ", "));
    std::vector<std::string> lines = {
      fmt::format("the closed forms' inputs (blocks from the free end): "
                  "alpha = {} against the true horizontal, W = {}, P = {}, "
                  "y = {:.4g} mm at the face joint",
                  values_text(inputs.inclination, 180. / M_PI, "deg"),
                  values_text(inputs.weight, 1. / kN, "kN/m"),
                  support,
                  inputs.floor_lift * 1e3)};
    for (const auto &difference : inputs.scene_differences)
      lines.push_back("the closed forms describe another scene than the "
                      "FEM's: " +
                      difference);
    return lines;
  }

  namespace
  {
    /** Which mechanisms assume the FEM's joint states, and how far off. */
    std::string
    holding_line(const Compare::JointStates     &states,
                 const Compare::JointComparison &face_joint)
    {
      const std::string joints = "the FEM's joints: " + states.text;
      if (states.holding.empty())
        return joints + "; none of the chapter's mechanisms assumes these "
                        "joint states, so none is expected to give the "
                        "FEM's Q";
      std::vector<std::string> named;
      for (const Scene::Mechanism mechanism : states.holding)
        for (const auto &force : face_joint.forces)
          if (force.mechanism == Scene::to_string(mechanism))
            named.push_back(
              force.difference_status == Compare::DifferenceStatus::defined ?
                fmt::format("{} (the FEM {:+.3g} % from it at the face joint)",
                            force.mechanism,
                            100. * force.relative_difference) :
                fmt::format("{} (no difference: {})",
                            force.mechanism,
                            force.has_value ?
                              Compare::to_string(force.difference_status) :
                              force.status));
      return joints + "; the mechanisms that assume these states: " +
             fmt::format("{}", fmt::join(named, "; "));
    }
  } // namespace

  namespace
  {
    /**
     * Joints 1..k where the FEM's chain slips on every joint, as the slip
     * mechanisms assume, and each one's largest difference there; "" when
     * joint 1 already does not slip.
     */
    std::string
    slip_chain_line(const RunComparison &comparison)
    {
      const auto &holds     = comparison.joint_states.slip_chain_holds;
      const auto  first_not = std::find(holds.begin(), holds.end(), false);
      const auto  k         = std::size_t(first_not - holds.begin());
      if (k == 0)
        return "";
      std::vector<std::string> differences;
      for (const Scene::Mechanism mechanism :
           {Scene::Mechanism::no_rotation,
            Scene::Mechanism::rotation_vertical_slip})
        {
          double largest = -1.;
          for (const auto &joint : comparison.final_joints)
            if (joint.joint <= k)
              for (const auto &force : joint.forces)
                if (force.mechanism == Scene::to_string(mechanism) &&
                    force.difference_status ==
                      Compare::DifferenceStatus::defined)
                  largest =
                    std::max(largest, std::abs(force.relative_difference));
          if (largest >= 0.)
            differences.push_back(
              fmt::format("{} {:.2g}", Scene::to_string(mechanism), largest));
        }
      if (differences.empty())
        return "";
      return fmt::format("joints 1 to {}: the FEM's blocks slip on every "
                         "joint up to there, as the slip mechanisms assume; "
                         "largest relative difference of their Q there: {}",
                         k,
                         fmt::join(differences, ", "));
    }
  } // namespace

  std::vector<std::string>
  verdicts(const RunComparison &comparison)
  {
    const Compare::JointComparison &face_joint = comparison.final_joints.back();
    std::vector<std::string> lines = closed_form_input_lines(comparison.inputs);
    if (!face_joint.load.carries_load())
      {
        lines.push_back(no_load_text(face_joint.load) +
                        " with the closed forms");
        return lines;
      }
    if (!comparison.inputs.scene_differences.empty())
      lines.push_back("no verdict on the lateral force Q: the FEM solves "
                      "another scene than the closed forms describe");
    else
      {
        lines.push_back(holding_line(comparison.joint_states, face_joint));
        const std::string chain = slip_chain_line(comparison);
        if (!chain.empty())
          lines.push_back(chain);
      }
    for (const auto &force : face_joint.forces)
      {
        if (force.difference_status == Compare::DifferenceStatus::other_scene)
          continue;
        if (!force.has_value)
          lines.push_back(force.mechanism + " has no finite Q (" +
                          force.status + ")");
        else if (force.difference_status != Compare::DifferenceStatus::defined)
          lines.push_back(fmt::format(
            "{} gives Q = 0 at the face joint, the FEM {:.4g} kN/m: no "
            "relative difference ({})",
            force.mechanism,
            face_joint.fem_force / kN,
            Compare::to_string(force.difference_status)));
        else
          lines.push_back(
            over_or_under(force.relative_difference,
                          "lateral force Q",
                          force.mechanism) +
            (force.status == "ok" ?
               "" :
               " (the mechanism itself is flagged " + force.status + ")"));
      }

    const auto &contact = face_joint.contact;
    const auto &formula = contact.closed_form;
    if (!has_closed_form(formula))
      {
        lines.push_back("Eqs. 6.51-6.53 have no answer at the face joint: " +
                        Analytic::describe(formula.status));
        return lines;
      }
    if (has_zero_reference(formula))
      {
        lines.push_back("Eqs. 6.51-6.53 give no contact at the face joint: "
                        "its Q is zero");
        return lines;
      }
    lines.push_back(over_or_under((contact.fem_area - formula.contact_area) /
                                    formula.contact_area,
                                  "contact area",
                                  "Eq. 6.51"));
    lines.push_back(
      over_or_under((contact.fem_mean_stress - formula.average_stress) /
                      formula.average_stress,
                    "mean contact stress",
                    "Eq. 6.52"));
    lines.push_back(
      over_or_under((contact.fem_averaged_peak_stress - formula.max_stress) /
                      formula.max_stress,
                    "averaged peak stress",
                    "Eq. 6.53"));
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
        const auto &mechanism = joints.front().forces[m];
        if (mechanism.closed_form_status != Analytic::Status::ok)
          {
            // Forces of an inadmissible mechanism are no answer: named in
            // the key, not drawn.
            plot += fmt::format(", NaN with dots lc rgb 'white' title '{}: "
                                "{}, not drawn'",
                                mechanism.mechanism,
                                mechanism.status);
            continue;
          }
        if (mechanism.difference_status ==
            Compare::DifferenceStatus::other_scene)
          {
            // Values of another scene are no comparison either.
            plot += fmt::format(", NaN with dots lc rgb 'white' title '{}: "
                                "describes another scene, not drawn'",
                                mechanism.mechanism);
            continue;
          }
        std::string rows;
        for (const auto &joint : joints)
          if (joint.forces[m].has_value)
            rows += fmt::format("{} {}\n",
                                joint.joint,
                                joint.forces[m].closed_form / kN);
        if (rows.empty())
          continue;
        data += fmt::format("$m{} << EOD\n{}EOD\n", m, rows);
        plot += fmt::format(", $m{} with linespoints title '{}'",
                            m,
                            joints.front().forces[m].mechanism);
      }
    return data +
           "set grid\nset key bottom right opaque\nset xlabel 'vertical joint j "
           "(n = face joint)'\nset ylabel 'Q_j (kN per m of face)'\n"
           "set title 'Lateral force per joint: FEM against the closed "
           "forms'\nset xtics 1\n" +
           plot + "\n";
  }

  json
  run_comparison_json(const RunComparison &comparison,
                      const unsigned int   n_blocks)
  {
    json history = json::array();
    for (const auto &point : comparison.lift_history)
      history.push_back(lift_history_entry(point.face_joint,
                                           comparison.constants,
                                           point.base_lift));
    const auto              &inputs = comparison.inputs;
    const auto              &states = comparison.joint_states;
    std::vector<std::string> holding;
    for (const Scene::Mechanism mechanism : states.holding)
      holding.push_back(Scene::to_string(mechanism));
    return {{"fem_joint_states",
             {{"vertical_friction_use", states.vertical_use},
              {"bedding_friction_use", states.bedding_use},
              {"open_beds", states.open_beds},
              {"slip_chain_holds", states.slip_chain_holds},
              {"holding_mechanisms", holding},
              {"text", states.text}}},
            {"closed_form_inputs",
             {{"alpha_rad", inputs.inclination},
              {"W_N_per_m", inputs.weight},
              {"P_N_per_m", inputs.support_load},
              {"y_m", inputs.floor_lift},
              {"scene_differences", inputs.scene_differences}}},
            {"final",
             comparison_json(comparison.final_joints,
                             comparison.constants,
                             n_blocks)},
            {"lift_history", history}};
  }

  std::string
  lift_history_plot(const std::vector<LiftHistoryPoint> &lift_history)
  {
    std::string data = "$h << EOD\n";
    for (const auto &point : lift_history)
      {
        const auto &contact = point.face_joint.contact;
        const auto &formula = contact.closed_form;
        const bool  defined = Analytic::has_contact_values(formula.status);
        const auto  cell = [defined](const double value, const double scale) {
          return defined ? fmt::format("{}", value * scale) :
                            std::string("NaN");
        };
        data += fmt::format("{} {} {} {} {}\n",
                            point.base_lift * 1e3,
                            contact.fem_area,
                            cell(formula.contact_area, 1.),
                            contact.fem_averaged_peak_stress * (1. / MPa),
                            cell(formula.max_stress, 1. / MPa));
      }
    data += "EOD\n";
    return data +
           "set multiplot layout 1,2 title 'Face joint along the floor "
           "lift'\nset grid\nset key top left\nset xlabel 'base lift (mm)'\n"
           "set ylabel 'contact area over b (m^2)'\n"
           "plot $h using 1:2 with linespoints title 'FEM', $h using 1:3 "
           "with linespoints title 'Eq. 6.51 (status ok only)'\n"
           "set ylabel 'sigma_max (MPa)'\n"
           "plot $h using 1:4 with linespoints title 'FEM (averaged peak)', "
           "$h using 1:5 with linespoints title 'Eq. 6.53 (status ok only)'\n"
           "unset multiplot\n";
  }

  std::string
  traction_profile_plot(const Contact::JointReport &face_joint)
  {
    // Ordered and plotted by the position along the joint: on a rounded
    // corner the nodes differ in height by less than a millimetre, so
    // against height the fillet's falling traction would draw as a line
    // back to zero at the top.
    std::vector<const Contact::JointNodeSample *> samples;
    for (const auto &sample : face_joint.profile)
      samples.push_back(&sample);
    std::stable_sort(samples.begin(),
                     samples.end(),
                     [](const auto *a, const auto *b) {
                       return a->arc_position < b->arc_position;
                     });
    std::string data = "$p << EOD\n";
    for (const Contact::JointNodeSample *sample : samples)
      data += fmt::format("{} {}\n",
                          sample->arc_position,
                          sample->normal_traction / MPa);
    data += "EOD\n";
    return data +
           "set grid\nunset key\nset xlabel 'normal traction (MPa, "
           "compression > 0)'\nset ylabel 'position along the joint (m, "
           "arc_position_m of joint_profiles.csv)'\nset title 'Normal traction along the face "
           "joint at the final lift'\n"
           "plot $p using 2:1 with linespoints pt 7 ps 0.6\n";
  }
} // namespace FloorBlock::Output
