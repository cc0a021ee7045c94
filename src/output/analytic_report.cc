#include <common/units.h>
#include <output/admissible_values.h>
#include <output/analytic_report.h>
#include <output/numbering_note.h>

#include <fmt/format.h>

namespace FloorBlock::Output
{
  using nlohmann::json;

  namespace
  {
    json
    contact_json(const Scene::MechanismResult &entry,
                 const Scene::ClosedForms     &closed_forms)
    {
      const auto            &contact = entry.contact;
      const Analytic::Status status  = face_contact_status(entry);
      json contact_values = {{"status", Analytic::to_string(status)},
              {"status_text", Analytic::describe(status)},
              {"Q_N", entry.face_force_over_width},
              {"y_m", closed_forms.floor_lift},
              {"E_Pa", closed_forms.youngs_modulus},
              {"b_m", closed_forms.support_width},
              {"L_m", closed_forms.chain.block_width},
              {"A_m2", contact.contact_area},
              {"contact_length_m", contact.contact_length},
              {"sigma_avg_Pa", contact.average_stress},
              {"sigma_max_Pa", contact.max_stress}};
      // Absent, not null, where Eq. 6.53 has no positive sigma_max.
      if (entry.floor_safety_factor)
        contact_values["safety_factor_eq_6_53"] = *entry.floor_safety_factor;
      return contact_values;
    }

    std::vector<double>
    scaled(const std::vector<double> &values, const double factor)
    {
      std::vector<double> result;
      for (const double value : values)
        result.push_back(value * factor);
      return result;
    }

    json
    mechanism_json(const Scene::MechanismResult &entry,
                   const Scene::ClosedForms     &closed_forms)
    {
      const auto &forces = entry.forces;
      return {{"status", Analytic::to_string(forces.status)},
              {"status_text", Analytic::describe(forces.status)},
              {"failing_block", forces.failing_block},
              {"Q_N_per_m", forces.lateral_force},
              {"Q_N_over_b",
               scaled(forces.lateral_force, closed_forms.support_width)},
              {"N_N_per_m", forces.normal_force},
              {"V_N_per_m", forces.joint_shear},
              {"normal_force_offset_m", forces.normal_force_offset},
              {"contact", contact_json(entry, closed_forms)}};
    }
  } // namespace

  json
  analytic_json(const Scene::ClosedForms &closed_forms)
  {
    const auto &chain = closed_forms.chain;
    json        cases;
    for (const auto &entry : closed_forms.mechanisms)
      cases[Scene::to_string(entry.mechanism)] =
        mechanism_json(entry, closed_forms);

    const auto &heights = closed_forms.no_rotation_heights;
    cases["no_rotation"]["centroid_height_m"]    = heights.centroid_height;
    cases["no_rotation"]["rotation_margin_m"]    = heights.rotation_margin;
    cases["no_rotation"]["first_rotating_block"] = heights.first_rotating_block;
    cases["no_rotation"]["centroid_status"] =
      Analytic::to_string(heights.status);

    return {{"numbering", numbering_note},
            {"forces_per",
             "Q_N_per_m, N_N_per_m, V_N_per_m are per metre of "
             "face; Q_N_over_b and contact.Q_N are over the "
             "support width b"},
            {"blocks",
             {{"W_N_per_m", chain.weight},
              {"P_N_per_m", chain.support_load},
              {"alpha_rad", chain.inclination},
              {"L_m", chain.block_width},
              {"H_m", chain.block_height},
              {"phi_h_rad", chain.bedding_friction},
              {"phi_v_rad", chain.vertical_friction}}},
            {"floor_strength_Pa", closed_forms.floor_strength},
            {"floor_strength_text",
             "the rock mass's uniaxial compressive strength sigma_ci s^a "
             "(Strength/); safety_factor_eq_6_53 = floor_strength_Pa / "
             "sigma_max_Pa, absent where Eq. 6.53 gives no positive sigma_max"},
            {"cases", cases}};
  }

  std::string
  analytic_csv(const Scene::ClosedForms &closed_forms)
  {
    std::string csv = fmt::format("# {}\n# Forces per metre of face; "
                                  "empty cells: the mechanism has no finite, "
                                  "admissible answer (see its status column; "
                                  "no_rotation_h_m follows "
                                  "no_rotation_status).\n",
                                  numbering_note);
    csv += "block,W_N_per_m,P_N_per_m,alpha_deg";
    for (const auto &entry : closed_forms.mechanisms)
      {
        const std::string name = Scene::to_string(entry.mechanism);
        csv += fmt::format(",{0}_status,{0}_Q_N_per_m,{0}_N_N_per_m", name);
      }
    csv += ",no_rotation_h_m\n";

    const auto &chain = closed_forms.chain;
    const auto  cell  = [](const Scene::MechanismResult &entry,
                         const std::vector<double>    &values,
                         const std::size_t             i) {
      return has_admissible_forces(entry) && i < values.size() ?
                 fmt::format("{:.9e}", values[i]) :
                 std::string();
    };
    for (std::size_t i = 0; i < chain.n_blocks(); ++i)
      {
        csv += fmt::format("{},{:.9e},{:.9e},{:.6f}",
                           i + 1,
                           chain.weight[i],
                           chain.support_load[i],
                           Units::radians_to_degrees(chain.inclination[i]));
        for (const auto &entry : closed_forms.mechanisms)
          csv += fmt::format(",{},{},{}",
                             Analytic::to_string(entry.forces.status),
                             cell(entry, entry.forces.lateral_force, i),
                             cell(entry, entry.forces.normal_force, i));
        // The heights come from no_rotation's Q, so they share its status.
        csv += "," +
               cell(closed_forms.mechanisms.front(),
                    closed_forms.no_rotation_heights.centroid_height,
                    i) +
               "\n";
      }
    return csv;
  }

  std::string
  analytic_table(const Scene::ClosedForms &closed_forms)
  {
    using Units::kN;
    using Units::MPa;
    const double b = closed_forms.support_width;
    std::string  text;
    for (const auto &entry : closed_forms.mechanisms)
      {
        const auto &forces = entry.forces;
        text += fmt::format("\n{}: {}\n",
                            Scene::to_string(entry.mechanism),
                            Analytic::describe(forces.status));
        if (forces.lateral_force.empty())
          continue;
        const bool admissible = has_admissible_forces(entry);
        if (!admissible)
          text += "  the equations' values, no answer of the model:\n";
        text += fmt::format("  {:>5} {:>14} {:>16} {:>12}\n",
                            "block",
                            "Q_i (kN/m)",
                            "Q_i over b (kN)",
                            "N_i (kN/m)");
        for (std::size_t i = 0; i < forces.lateral_force.size(); ++i)
          text += fmt::format("  {:>5} {:>14.1f} {:>16.1f} {:>12.1f}\n",
                              i + 1,
                              forces.lateral_force[i] / kN,
                              forces.lateral_force[i] * b / kN,
                              forces.normal_force[i] / kN);
        if (!admissible)
          {
            text += fmt::format(
              "  face joint: Eqs. 6.51-6.53 not evaluated, the mechanism is "
              "{}\n",
              Analytic::to_string(forces.status));
            continue;
          }
        const auto &contact = entry.contact;
        text += fmt::format(
          "  face joint: Q = {:.1f} kN over b = {:.2f} m, y = {:.4f} m -> "
          "A = {:.4f} m^2, sigma_avg = {:.2f} MPa, sigma_max = {:.2f} MPa "
          "[{}]\n",
          entry.face_force_over_width / kN,
          b,
          closed_forms.floor_lift,
          contact.contact_area,
          contact.average_stress / MPa,
          contact.max_stress / MPa,
          Analytic::to_string(contact.status));
        if (entry.floor_safety_factor)
          text += fmt::format(
            "  floor at the face: FS = sigma_c / sigma_max = {:.2f} MPa / "
            "{:.2f} MPa = {:.2f} (the chapter's route; {})\n",
            closed_forms.floor_strength / MPa,
            contact.max_stress / MPa,
            *entry.floor_safety_factor,
            *entry.floor_safety_factor < 1. ? "the corner fails" :
                                              "the corner holds");
      }
    const auto &heights = closed_forms.no_rotation_heights;
    if (!heights.centroid_height.empty())
      {
        text +=
          "\nno_rotation lateral-force heights h_i (m) and margin H - h_i "
          "(negative: the block rotates):\n";
        for (std::size_t i = 0; i < heights.centroid_height.size(); ++i)
          text += fmt::format("  block {:>2}: h = {:.3f}, margin = {:+.3f}\n",
                              i + 1,
                              heights.centroid_height[i],
                              heights.rotation_margin[i]);
      }
    return text;
  }
} // namespace FloorBlock::Output
