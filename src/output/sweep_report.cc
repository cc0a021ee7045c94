#include <common/units.h>
#include <output/admissible_values.h>
#include <output/numbering_note.h>
#include <output/sweep_report.h>

#include <fmt/format.h>

#include <functional>
#include <map>
#include <optional>

namespace FloorBlock::Output
{
  namespace
  {
    using Units::kN;
    using Units::MPa;

    using PointValue =
      std::function<std::optional<double>(const Scene::FigurePoint &,
                                          const Scene::MechanismResult &)>;
    using PointKey = std::function<double(const Scene::FigurePoint &)>;

    /** A value every panel draws across as a dashed line, with its key. */
    struct HorizontalLine
    {
      double      value;
      std::string key;
    };

    /**
     * The scene rock's strength sigma_c (MPa) as a line of Figures
     * 6.10/6.11: the cases whose sigma_max lies above it have FS < 1 by
     * the chapter's route. The key stays short, as long as the curves'
     * keys: a longer one widens the key box over the curves of a panel a
     * third of the picture wide; the figure's title says the rest.
     */
    HorizontalLine
    strength_line(const Scene::FigurePoint &point)
    {
      const double strength = point.closed_forms.floor_strength / MPa;
      return {strength, fmt::format("sigma_c = {:.2f} MPa", strength)};
    }

    /**
     * A multiplot with one panel per mechanism and one curve per value of
     * @p curve_key; x is the bedding friction in degrees. Points without a
     * finite, admissible value are left out of their curve, and the panel's
     * title says how many. A @p line is drawn dashed across every panel
     * with an answer.
     */
    std::string
    panels_by_mechanism(const std::vector<const Scene::FigurePoint *> &points,
                        const std::string                             &title,
                        const std::string                             &y_label,
                        const PointKey                      &curve_key,
                        const std::string                   &curve_label_format,
                        const PointValue                    &value,
                        const std::optional<HorizontalLine> &line = {})
    {
      std::string script = fmt::format(
        "set multiplot layout 1,3 title '{}'\nset grid\nset key top left\n"
        "set xlabel 'bedding friction angle (deg)'\nset ylabel '{}'\n"
        "set xrange [10:35]\n",
        title,
        y_label);
      const auto &mechanisms = points.front()->closed_forms.mechanisms;
      for (std::size_t m = 0; m < mechanisms.size(); ++m)
        {
          std::map<double, std::string> curves;
          std::size_t                   n_left_out = 0;
          for (const Scene::FigurePoint *point : points)
            if (const auto y = value(*point, point->closed_forms.mechanisms[m]))
              curves[curve_key(*point)] +=
                fmt::format("{} {}\n",
                            Units::radians_to_degrees(point->bedding_friction),
                            *y);
            else
              ++n_left_out;
          script +=
            fmt::format("set title \"{}{}\"\n",
                        Scene::to_string(mechanisms[m].mechanism),
                        n_left_out == 0 ?
                          std::string() :
                          fmt::format("\\n{} of {} points not ok: not drawn",
                                      n_left_out,
                                      points.size()));
          if (curves.empty())
            {
              script += "set label 1 'no admissible answer' at graph 0.25,0.5\n"
                        "plot [10:35] [0:1] NaN notitle\nunset label 1\n";
              continue;
            }
          std::string  plot = "plot ";
          std::string  data;
          unsigned int index = 0;
          for (const auto &[key, rows] : curves)
            {
              data += fmt::format("$c{}_{} << EOD\n{}EOD\n", m, index, rows);
              plot += fmt::format("{}$c{}_{} with linespoints title '{}'",
                                  index == 0 ? "" : ", ",
                                  m,
                                  index,
                                  fmt::format(curve_label_format, key));
              ++index;
            }
          if (line)
            plot +=
              fmt::format(", {} with lines dt 2 lw 2 lc rgb 'black' title '{}'",
                          line->value,
                          line->key);
          script += data + plot + "\n";
        }
      return script + "unset multiplot\n";
    }

    std::vector<const Scene::FigurePoint *>
    select(const std::vector<Scene::FigurePoint>                 &points,
           const std::function<bool(const Scene::FigurePoint &)> &keep)
    {
      std::vector<const Scene::FigurePoint *> selected;
      for (const auto &point : points)
        if (keep(point))
          selected.push_back(&point);
      return selected;
    }
  } // namespace

  std::string
  sweep_csv(const std::vector<Scene::FigurePoint> &points)
  {
    std::string csv = fmt::format(
      "# {}\n# Q_face: Q_n between block n and the face block. Empty cells: "
      "no finite, admissible answer (see the status columns; the corner "
      "contact's status is its mechanism's when that is not ok).\n# "
      "floor_strength_Pa: the rock mass's uniaxial compressive strength "
      "sigma_ci s^a (Strength/); <mechanism>_safety_factor_eq_6_53 = "
      "floor_strength_Pa / <mechanism>_sigma_max_Pa, the chapter's route, "
      "empty where sigma_max is empty or not positive.\n",
      numbering_note);
    csv += "figure,k_m,phi_h_deg,phi_v_deg,support_load_t,y_m,"
           "floor_strength_Pa";
    for (const auto &entry : points.front().closed_forms.mechanisms)
      csv += fmt::format(
        ",{0}_status,{0}_Q_face_N_per_m,{0}_Q_face_N_over_b,{0}_A_m2,"
        "{0}_sigma_max_Pa,{0}_contact_status,{0}_safety_factor_eq_6_53",
        Scene::to_string(entry.mechanism));
    csv += "\n";

    for (const auto &point : points)
      {
        csv +=
          fmt::format("{},{},{:.3f},{:.3f},{:.3f},{:.9e},{:.9e}",
                      point.figure,
                      point.curvature,
                      Units::radians_to_degrees(point.bedding_friction),
                      Units::radians_to_degrees(point.vertical_friction),
                      point.support_load / Units::tonnes_force_to_newtons(1.0),
                      point.closed_forms.floor_lift,
                      point.closed_forms.floor_strength);
        for (const auto &entry : point.closed_forms.mechanisms)
          {
            csv += "," + Analytic::to_string(entry.forces.status);
            csv += has_admissible_forces(entry) ?
                     fmt::format(",{:.9e},{:.9e}",
                                 entry.forces.lateral_force.back(),
                                 entry.face_force_over_width) :
                     std::string(",,");
            csv += has_admissible_contact(entry) ?
                     fmt::format(",{:.9e},{:.9e}",
                                 entry.contact.contact_area,
                                 entry.contact.max_stress) :
                     std::string(",,");
            csv += "," + Analytic::to_string(face_contact_status(entry));
            // Scene::evaluate_closed_forms() sets the factor only where
            // sigma_max is admissible and positive.
            csv += entry.floor_safety_factor ?
                     fmt::format(",{:.9e}", *entry.floor_safety_factor) :
                     std::string(",");
          }
        csv += "\n";
      }
    return csv;
  }

  std::string
  lateral_force_plot(const std::vector<Scene::FigurePoint> &points,
                     const std::string                     &figure,
                     const std::string                     &title)
  {
    return panels_by_mechanism(
      select(points,
             [&](const Scene::FigurePoint &p) { return p.figure == figure; }),
      title,
      "Q at the face over b (kN)",
      [](const Scene::FigurePoint &p) {
        return Units::radians_to_degrees(p.vertical_friction);
      },
      "phi_v = {:.0f} deg",
      [](const Scene::FigurePoint &,
         const Scene::MechanismResult &entry) -> std::optional<double> {
        if (!has_admissible_forces(entry))
          return std::nullopt;
        return entry.face_force_over_width / kN;
      });
  }

  std::string
  floor_stress_plot(const std::vector<Scene::FigurePoint> &points,
                    const double                           curvature)
  {
    return panels_by_mechanism(
      select(points,
             [&](const Scene::FigurePoint &p) {
               return p.curvature == curvature;
             }),
      fmt::format("sigma_max at the face (Eq. 6.53), y = x^2/{:.0f}; dashed: "
                  "rock mass strength sigma_c = {:.2f} MPa (Strength/), above "
                  "it FS = sigma_c / sigma_max < 1",
                  curvature,
                  points.front().closed_forms.floor_strength / MPa),
      "sigma_max (MPa)",
      [](const Scene::FigurePoint &p) {
        return p.support_load / Units::tonnes_force_to_newtons(1.0);
      },
      "{:.0f} t",
      [](const Scene::FigurePoint &,
         const Scene::MechanismResult &entry) -> std::optional<double> {
        if (!has_admissible_contact(entry))
          return std::nullopt;
        return entry.contact.max_stress / MPa;
      },
      strength_line(points.front()));
  }
} // namespace FloorBlock::Output
