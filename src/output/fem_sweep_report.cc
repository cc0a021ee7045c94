#include <common/units.h>
#include <output/fem_sweep_report.h>
#include <output/gnuplot.h>
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
    constexpr double kN  = Units::newtons_per_kilonewton;
    constexpr double MPa = Units::pascals_per_megapascal;

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
    cell(const json &value, const double scale = 1.)
    {
      return value.is_number() ? fmt::format("{:.9e}", value.get<double>() * scale) :
                                 std::string();
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
  } // namespace

  json
  fem_case_record(const Scene::FigurePoint   &point,
                  const Contact::SolveResult &result,
                  const FemReport            &report)
  {
    const Contact::JointReport *face =
      face_joint(result, point.closed_forms.chain.n_blocks());
    const auto of_face = [face](const double Contact::JointReport::*member) {
      return face ? json(face->*member) : json(nullptr);
    };
    json closed = json::object();
    for (const auto &entry : point.closed_forms.mechanisms)
      {
        const bool has_q = !entry.forces.lateral_force.empty();
        const bool has_stress =
          has_q && entry.contact.status == Analytic::Status::ok;
        closed[Scene::to_string(entry.mechanism)] = {
          {"status", Analytic::to_string(entry.forces.status)},
          {"Q_face_N_per_m",
           has_q ? json(entry.forces.lateral_force.back()) : json(nullptr)},
          {"sigma_max_6_53_Pa",
           has_stress ? json(entry.contact.max_stress) : json(nullptr)},
          {"contact_status", Analytic::to_string(entry.contact.status)}};
      }
    return {
      {"id", point.id()},
      {"figure", point.figure},
      {"k_m", point.curvature},
      {"phi_h_deg", as_written(Units::radians_to_degrees(point.bedding_friction))},
      {"phi_v_deg",
       as_written(Units::radians_to_degrees(point.vertical_friction))},
      {"support_load_t",
       as_written(point.support_load / Units::tonnes_force_to_newtons(1.))},
      {"fem",
       {{"status", report.status},
        {"status_text", report.status_text},
        {"model", report.model},
        {"Q_face_N_per_m", of_face(&Contact::JointReport::normal_force)},
        {"contact_length_m", of_face(&Contact::JointReport::closed_length)},
        {"sigma_max_Pa", of_face(&Contact::JointReport::peak_normal_stress)},
        {"sigma_max_averaged_Pa",
         of_face(&Contact::JointReport::averaged_peak_normal_stress)},
        {"n_dofs", result.n_dofs},
        {"wall_time_s", result.wall_times}}},
      {"closed_forms", closed}};
  }

  std::string
  fem_sweep_csv(const std::vector<json> &records, const std::string &figure)
  {
    std::string csv = fmt::format(
      "# {}\n# Face joint (Q_n). FEM values are empty where the FEM did not "
      "converge (fem_status); closed-form values are empty where the "
      "formula has no finite answer (its status).\n"
      "k_m,phi_h_deg,phi_v_deg,support_load_t,fem_status,fem_Q_face_N_per_m,"
      "fem_contact_length_m,fem_sigma_max_Pa,fem_sigma_max_averaged_Pa",
      numbering_note);
    std::set<std::string> models;
    for (const auto &record : records)
      if (record["figure"] == figure)
        models.insert(record["fem"].value("model", "elastic FEM"));
    csv.insert(csv.find("\nk_m,") + 1,
               fmt::format("# fem_* columns computed by: {}.\n",
                           fmt::join(models, ", ")));
    const std::vector<std::string> mechanisms = {
      "no_rotation", "rotation_no_vertical_slip", "rotation_vertical_slip"};
    for (const auto &mechanism : mechanisms)
      csv += fmt::format(",{0}_status,{0}_Q_face_N_per_m,{0}_sigma_max_6_53_Pa",
                         mechanism);
    csv += "\n";
    for (const auto &record : records)
      {
        if (record["figure"] != figure)
          continue;
        const auto &fem = record["fem"];
        const bool  ok  = fem["status"] == "converged";
        csv += fmt::format("{},{},{},{},{},{},{},{},{}", record["k_m"].dump(),
                           record["phi_h_deg"].dump(),
                           record["phi_v_deg"].dump(),
                           record["support_load_t"].dump(),
                           fem["status"].get<std::string>(),
                           ok ? cell(fem["Q_face_N_per_m"]) : "",
                           ok ? cell(fem["contact_length_m"]) : "",
                           ok ? cell(fem["sigma_max_Pa"]) : "",
                           ok ? cell(fem["sigma_max_averaged_Pa"]) : "");
        for (const auto &mechanism : mechanisms)
          {
            const auto &closed = record["closed_forms"][mechanism];
            csv += fmt::format(",{},{},{}", closed["status"].get<std::string>(),
                               cell(closed["Q_face_N_per_m"]),
                               cell(closed["sigma_max_6_53_Pa"]));
          }
        csv += "\n";
      }
    return csv;
  }

  std::string
  fem_sweep_plot(const std::vector<json> &records, const std::string &figure)
  {
    const bool  stress   = is_stress_figure(figure);
    const char *panel_by = stress ? "k_m" : "phi_v_deg";
    const char *curve_by = stress ? "support_load_t" : "phi_v_deg";
    const char *fem_key  = stress ? "sigma_max_averaged_Pa" : "Q_face_N_per_m";
    const char *closed_key = stress ? "sigma_max_6_53_Pa" : "Q_face_N_per_m";
    const double scale     = stress ? 1. / MPa : 1. / kN;

    // panel -> curve -> rows "phi_h fem closed"
    std::map<double, std::map<double, std::string>> panels;
    for (const auto &record : records)
      if (record["figure"] == figure)
        {
          const auto &fem    = record["fem"];
          const auto &closed = record["closed_forms"]["no_rotation"];
          const auto  value  = [&](const json &v) {
            return v.is_number() ? fmt::format("{}", v.get<double>() * scale) :
                                   std::string("NaN");
          };
          panels[record[panel_by].get<double>()]
                [record[curve_by].get<double>()] += fmt::format(
                  "{} {} {}\n", record["phi_h_deg"].get<double>(),
                  fem["status"] == "converged" ? value(fem[fem_key]) : "NaN",
                  value(closed[closed_key]));
        }

    std::string script = fmt::format(
      "set multiplot layout 1,{} title '{}: FEM (points) against the "
      "no-rotation closed form (lines)'\nset grid\nset key top left\n"
      "set xlabel 'bedding friction angle (deg)'\nset ylabel '{}'\n",
      std::max<std::size_t>(panels.size(), 1), figure,
      stress ? "sigma_max at the face (MPa)" : "Q at the face (kN/m)");
    unsigned int block = 0;
    for (const auto &[panel, curves] : panels)
      {
        script += fmt::format("set title '{} = {}'\n", panel_by, panel);
        std::string plot = "plot ";
        for (const auto &[curve, rows] : curves)
          {
            script += fmt::format("$d{} << EOD\n{}EOD\n", block, rows);
            plot += fmt::format(
              "{}$d{} using 1:2 with points pt 7 lc {} title 'FEM {} {}', "
              "$d{} using 1:3 with lines lc {} notitle",
              block == 0 || plot == "plot " ? "" : ", ", block, block % 8 + 1,
              curve_by, curve, block, block % 8 + 1);
            ++block;
          }
        script += plot + "\n";
      }
    return script + "unset multiplot\n";
  }

  std::size_t
  write_fem_sweep(const CaseStore                &store,
                  const std::vector<std::string> &case_ids,
                  const ResultFolder             &folder)
  {
    std::vector<json> records;
    for (const std::string &id : case_ids)
      if (store.has(id))
        records.push_back(store.load(id));
    std::set<std::string> figures;
    for (const auto &record : records)
      figures.insert(record["figure"].get<std::string>());
    for (const std::string &figure : figures)
      {
        folder.write("sweep_fem_" + figure + ".csv",
                     fem_sweep_csv(records, figure));
        render_png(fem_sweep_plot(records, figure),
                   folder.path_of("sweep_fem_" + figure + ".png"), 1600, 500);
      }
    return records.size();
  }
} // namespace FloorBlock::Output
