#include <common/units.h>
#include <output/admissible_values.h>
#include <output/fem_sweep_report.h>
#include <output/gnuplot.h>
#include <output/json_values.h>
#include <output/numbering_note.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <map>
#include <set>

namespace FloorBlock::Output
{
  using nlohmann::json;

  namespace
  {
    using Units::kN;
    using Units::MPa;

    /** The face joint of the last converged increment, if any. */
    const Contact::JointReport *
    face_joint(const Contact::SolveResult &result, const unsigned int n_blocks)
    {
      if (!result.increments.empty())
        for (const auto &joint : result.increments.back().joints)
          if (joint.name == "vertical " + std::to_string(n_blocks))
            return &joint;
      return nullptr;
    }

    std::string
    cell(const std::optional<double> &value, const double scale = 1.)
    {
      return value ? fmt::format("{:.9e}", *value * scale) : std::string();
    }

    /// A number as JSON writes it (400.0, 12.5), as the CSV always had.
    std::string
    as_json(const double value)
    {
      return json(value).dump();
    }

    /// Degrees and tonnes as the user wrote them (30, not 29.999999999999996).
    double
    as_written(const double value)
    {
      constexpr double resolution = 1e6;
      return std::round(value * resolution) / resolution;
    }

    bool
    is_stress_figure(const std::string &figure)
    {
      return figure == "fig6_10_11";
    }

    /**
     * The face corner of a solve as the sweep reports it. A solve that
     * stopped early leaves the corner of its last converged increment, a
     * smaller load than the case's, so it gets no number, like the face
     * joint's columns.
     */
    FemFaceCorner
    face_corner(const FemReport &report, const unsigned int n_blocks)
    {
      if (!report.converged())
        return {"not converged", std::nullopt, std::nullopt};
      for (const Safety::CornerSafety &corner : report.corner_safety)
        if (corner.path.joint == n_blocks && corner.path.block == "face block")
          {
            if (!corner.resolved())
              return {"unresolved", std::nullopt, std::nullopt};
            return {"resolved",
                    corner.point_stresses.sigma_1,
                    corner.point_factor};
          }
      return {"not evaluated", std::nullopt, std::nullopt};
    }
  } // namespace

  FemCaseRecord
  fem_case_record(const Scene::FigurePoint   &point,
                  const Contact::SolveResult &result,
                  const FemReport            &report)
  {
    FemCaseRecord record;
    record.id        = point.id();
    record.figure    = point.figure;
    record.curvature = point.curvature;
    record.bedding_friction_deg =
      as_written(Units::radians_to_degrees(point.bedding_friction));
    record.vertical_friction_deg =
      as_written(Units::radians_to_degrees(point.vertical_friction));
    record.support_load_t =
      as_written(point.support_load / Units::tonnes_force_to_newtons(1.));
    record.status      = report.status;
    record.status_text = report.status_text;
    record.model       = report.model;
    if (const Contact::JointReport *face =
          face_joint(result, point.closed_forms.chain.n_blocks()))
      {
        record.face_force              = face->normal_force;
        record.face_contact_length     = face->closed_length;
        record.face_sigma_max          = face->peak_normal_stress;
        record.face_sigma_max_averaged = face->averaged_peak_normal_stress;
      }
    record.face_corner =
      face_corner(report, point.closed_forms.chain.n_blocks());
    record.n_dofs         = result.n_dofs;
    record.wall_times     = result.wall_times;
    record.floor_strength = point.closed_forms.floor_strength;
    for (const auto &entry : point.closed_forms.mechanisms)
      {
        record.closed_forms[Scene::to_string(entry.mechanism)] = {
          Analytic::to_string(entry.forces.status),
          has_admissible_forces(entry) ?
            std::optional<double>(entry.forces.lateral_force.back()) :
            std::nullopt,
          has_admissible_contact(entry) ?
            std::optional<double>(entry.contact.max_stress) :
            std::nullopt,
          Analytic::to_string(face_contact_status(entry)),
          entry.floor_safety_factor};
      }
    return record;
  }

  json
  fem_case_json(const FemCaseRecord &record)
  {
    json closed = json::object();
    for (const auto &[mechanism, entry] : record.closed_forms)
      closed[mechanism] = {
        {"status", entry.status},
        {"Q_face_N_per_m", optional_json(entry.face_force)},
        {"sigma_max_6_53_Pa", optional_json(entry.max_stress)},
        {"contact_status", entry.contact_status},
        {"safety_factor_eq_6_53", optional_json(entry.safety_factor)}};
    return {
      {"id", record.id},
      {"figure", record.figure},
      {"k_m", record.curvature},
      {"phi_h_deg", record.bedding_friction_deg},
      {"phi_v_deg", record.vertical_friction_deg},
      {"support_load_t", record.support_load_t},
      {"fem",
       {{"status", record.status},
        {"status_text", record.status_text},
        {"model", record.model},
        {"Q_face_N_per_m", optional_json(record.face_force)},
        {"contact_length_m", optional_json(record.face_contact_length)},
        {"sigma_max_Pa", optional_json(record.face_sigma_max)},
        {"sigma_max_averaged_Pa",
         optional_json(record.face_sigma_max_averaged)},
        {"face_corner",
         {{"status", record.face_corner.status},
          {"sigma_1_at_half_L_Pa", optional_json(record.face_corner.sigma_1)},
          {"safety_factor_point",
           optional_json(record.face_corner.point_factor)}}},
        {"n_dofs", record.n_dofs},
        {"wall_time_s", record.wall_times}}},
      {"floor_strength_Pa", optional_json(record.floor_strength)},
      {"closed_forms", closed}};
  }

  FemCaseRecord
  fem_case_from_json(const json &case_json)
  {
    FemCaseRecord record;
    record.id                    = case_json.at("id").get<std::string>();
    record.figure                = case_json.at("figure").get<std::string>();
    record.curvature             = case_json.at("k_m").get<double>();
    record.bedding_friction_deg  = case_json.at("phi_h_deg").get<double>();
    record.vertical_friction_deg = case_json.at("phi_v_deg").get<double>();
    record.support_load_t        = case_json.at("support_load_t").get<double>();
    const json &fem              = case_json.at("fem");
    record.status                = fem.at("status").get<std::string>();
    record.status_text           = fem.at("status_text").get<std::string>();
    record.model                 = fem.value("model", "elastic FEM");
    record.face_force            = optional_value(fem.at("Q_face_N_per_m"));
    record.face_contact_length   = optional_value(fem.at("contact_length_m"));
    record.face_sigma_max        = optional_value(fem.at("sigma_max_Pa"));
    record.face_sigma_max_averaged =
      optional_value(fem.at("sigma_max_averaged_Pa"));
    record.n_dofs = fem.at("n_dofs").get<unsigned int>();
    record.wall_times =
      fem.at("wall_time_s").get<std::map<std::string, double>>();
    // Case files written before the face corner and the strength were
    // stored lack them; a rerun keeps such files rather than solving again.
    if (fem.contains("face_corner"))
      {
        const json &corner        = fem.at("face_corner");
        record.face_corner.status = corner.at("status").get<std::string>();
        record.face_corner.sigma_1 =
          optional_value(corner.at("sigma_1_at_half_L_Pa"));
        record.face_corner.point_factor =
          optional_value(corner.at("safety_factor_point"));
      }
    record.floor_strength =
      optional_value(case_json.value("floor_strength_Pa", json()));
    for (const auto &[mechanism, entry] : case_json.at("closed_forms").items())
      record.closed_forms[mechanism] = {
        entry.at("status").get<std::string>(),
        optional_value(entry.at("Q_face_N_per_m")),
        optional_value(entry.at("sigma_max_6_53_Pa")),
        entry.at("contact_status").get<std::string>(),
        optional_value(entry.value("safety_factor_eq_6_53", json()))};
    return record;
  }

  std::string
  fem_sweep_csv(const std::vector<FemCaseRecord> &records,
                const std::string                &figure)
  {
    std::string csv = fmt::format(
      "# {}\n# Face joint (Q_n). FEM values are empty where the FEM did not "
      "converge (fem_status); closed-form values are empty where the "
      "formula has no finite, admissible answer (its status).\n# Face "
      "corner (the face block's at the face joint): the FEM's sigma_1 at "
      "L/2 along the corner's bisector (Strength/Critical distance L) and "
      "its Hoek-Brown factor (point method), empty unless "
      "fem_face_corner_status is resolved (Mesh/Cells per critical "
      "distance). floor_strength_Pa: the rock mass's uniaxial compressive "
      "strength sigma_ci s^a (Strength/); "
      "<mechanism>_safety_factor_eq_6_53 = floor_strength_Pa / "
      "<mechanism>_sigma_max_6_53_Pa, empty where that is empty or not "
      "positive.\n"
      "k_m,phi_h_deg,phi_v_deg,support_load_t,floor_strength_Pa,fem_status,"
      "fem_Q_face_N_per_m,fem_contact_length_m,fem_sigma_max_Pa,"
      "fem_sigma_max_averaged_Pa,fem_face_corner_status,"
      "fem_sigma_1_at_half_L_Pa,fem_safety_factor_point",
      numbering_note);
    std::set<std::string> models;
    for (const auto &record : records)
      if (record.figure == figure)
        models.insert(record.model);
    csv.insert(csv.find("\nk_m,") + 1,
               fmt::format("# fem_* columns computed by: {}.\n",
                           fmt::join(models, ", ")));
    const std::vector<std::string> mechanisms = {"no_rotation",
                                                 "rotation_no_vertical_slip",
                                                 "rotation_vertical_slip"};
    for (const auto &mechanism : mechanisms)
      csv += fmt::format(",{0}_status,{0}_Q_face_N_per_m,{0}_sigma_max_6_53_Pa,"
                         "{0}_safety_factor_eq_6_53",
                         mechanism);
    csv += "\n";
    for (const auto &record : records)
      {
        if (record.figure != figure)
          continue;
        const bool ok = record.status == "converged";
        csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{}",
                           as_json(record.curvature),
                           as_json(record.bedding_friction_deg),
                           as_json(record.vertical_friction_deg),
                           as_json(record.support_load_t),
                           cell(record.floor_strength),
                           record.status,
                           ok ? cell(record.face_force) : "",
                           ok ? cell(record.face_contact_length) : "",
                           ok ? cell(record.face_sigma_max) : "",
                           ok ? cell(record.face_sigma_max_averaged) : "",
                           record.face_corner.status,
                           cell(record.face_corner.sigma_1),
                           cell(record.face_corner.point_factor));
        for (const auto &mechanism : mechanisms)
          {
            const auto &closed = record.closed_forms.at(mechanism);
            csv += fmt::format(",{},{},{},{}",
                               closed.status,
                               cell(closed.face_force),
                               cell(closed.max_stress),
                               cell(closed.safety_factor));
          }
        csv += "\n";
      }
    return csv;
  }

  std::string
  fem_sweep_plot(const std::vector<FemCaseRecord> &records,
                 const std::string                &figure)
  {
    const bool   stress   = is_stress_figure(figure);
    const char  *panel_by = stress ? "k_m" : "phi_v_deg";
    const char  *curve_by = stress ? "support_load_t" : "phi_v_deg";
    const double scale    = stress ? 1. / MPa : 1. / kN;

    // panel -> curve -> rows "phi_h fem closed face_corner"
    std::map<double, std::map<double, std::string>> panels;
    std::optional<double>                           strength;
    for (const auto &record : records)
      if (record.figure == figure)
        {
          const auto &closed = record.closed_forms.at("no_rotation");
          const auto  value  = [&](const std::optional<double> &v) {
            return v ? fmt::format("{}", *v * scale) : std::string("NaN");
          };
          const double panel =
            stress ? record.curvature : record.vertical_friction_deg;
          const double curve =
            stress ? record.support_load_t : record.vertical_friction_deg;
          panels[panel][curve] +=
            fmt::format("{} {} {} {}\n",
                        record.bedding_friction_deg,
                        record.status == "converged" ?
                          value(stress ? record.face_sigma_max_averaged :
                                         record.face_force) :
                          "NaN",
                        value(stress ? closed.max_stress : closed.face_force),
                        value(record.face_corner.sigma_1));
          if (!strength)
            strength = record.floor_strength;
        }
    // Only Figures 6.10/6.11 are stresses to hold against the strength.
    std::string strength_title, strength_line;
    if (stress && strength)
      {
        strength_title = fmt::format(
          "; dashed: rock mass strength sigma_c = {:.2f} MPa (Strength/)",
          *strength / MPa);
        strength_line = fmt::format(
          ", {} with lines dt 2 lw 2 lc rgb 'black' title 'sigma_c = {:.2f} "
          "MPa'",
          *strength / MPa,
          *strength / MPa);
      }

    std::string script = fmt::format(
      "set multiplot layout 1,{} title '{}: FEM (points) against the "
      "no-rotation closed form (lines){}'\nset grid\nset key top left\n"
      "set xlabel 'bedding friction angle (deg)'\nset ylabel '{}'\n",
      std::max<std::size_t>(panels.size(), 1),
      figure,
      strength_title,
      stress ? "stress at the face (MPa)" : "Q at the face (kN/m)");
    unsigned int block = 0;
    for (const auto &[panel, curves] : panels)
      {
        script += fmt::format("set title '{} = {}'\n", panel_by, panel);
        std::string plot = "plot ";
        // Colours by the curve's place in its panel: a support load or
        // friction has one colour in every panel.
        unsigned int colour = 1;
        for (const auto &[curve, rows] : curves)
          {
            script += fmt::format("$d{} << EOD\n{}EOD\n", block, rows);
            plot += fmt::format(
              "{}$d{} using 1:2 with points pt 7 lc {} title 'FEM {} {}', "
              "$d{} using 1:3 with lines lc {} notitle",
              plot == "plot " ? "" : ", ",
              block,
              colour,
              curve_by,
              curve,
              block,
              colour);
            if (stress)
              plot += fmt::format(
                ", $d{} using 1:4 with points pt 6 ps 1.5 lc {} notitle",
                block,
                colour);
            ++block;
            colour = colour % 8 + 1;
          }
        // One key entry per symbol, in black: the colours are the curves'.
        if (stress)
          plot += ", NaN with points pt 6 ps 1.5 lc rgb 'black' title 'FEM "
                  "sigma_1 at L/2 (face corner)'";
        script += plot + strength_line + "\n";
      }
    return script + "unset multiplot\n";
  }

  std::size_t
  write_fem_sweep(const CaseStore                &store,
                  const std::vector<std::string> &case_ids,
                  const ResultFolder             &folder)
  {
    std::vector<FemCaseRecord> records;
    for (const std::string &id : case_ids)
      if (store.has(id))
        records.push_back(fem_case_from_json(store.load(id)));
    std::set<std::string> figures;
    for (const auto &record : records)
      figures.insert(record.figure);
    for (const std::string &figure : figures)
      {
        folder.write("sweep_fem_" + figure + ".csv",
                     fem_sweep_csv(records, figure));
        render_png(fem_sweep_plot(records, figure),
                   folder.path_of("sweep_fem_" + figure + ".png"),
                   1600,
                   500);
      }
    return records.size();
  }
} // namespace FloorBlock::Output
