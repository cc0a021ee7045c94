#include <common/units.h>
#include <output/governing_report.h>

#include <fmt/format.h>

namespace FloorBlock::Output
{
  using nlohmann::json;
  using Units::kN;
  using Units::MPa;

  namespace
  {
    /** A figure's value in the unit of the report (kN/m or MPa). */
    std::string
    in_report_unit(const Compare::GoverningJoint &entry, const double value)
    {
      return entry.figure == "Q_N_per_m" ?
               fmt::format("{:.1f} kN/m", value / kN) :
               fmt::format("{:.2f} MPa", value / MPa);
    }

    const Compare::GoverningJoint *
    find_figure(const std::vector<Compare::GoverningJoint> &governing,
                const std::string                          &figure)
    {
      for (const auto &entry : governing)
        if (entry.figure == figure)
          return &entry;
      return nullptr;
    }
  } // namespace

  json
  governing_json(const std::vector<Compare::GoverningJoint> &governing)
  {
    json list = json::array();
    for (const auto &entry : governing)
      list.push_back({{"figure", entry.figure},
                      {"description", entry.description},
                      {"joint", entry.joint},
                      {"value", entry.value},
                      {"x_m", entry.x},
                      {"y_m", entry.y},
                      {"face_joint", entry.face_joint},
                      {"face_joint_value", entry.face_value},
                      {"face_joint_governs", entry.is_face_joint()}});
    return list;
  }

  std::string
  governing_table_markdown(
    const std::vector<Compare::GoverningJoint> &governing)
  {
    std::string text =
      "| figure | governing joint | value | at x, y (m) | face joint |\n"
      "|---|---|---|---|---|\n";
    for (const auto &entry : governing)
      text += fmt::format("| {} | {}{} | {} | {:.3f}, {:.3f} | {} |\n",
                          entry.description,
                          entry.joint,
                          entry.is_face_joint() ? " (the face joint)" : "",
                          in_report_unit(entry, entry.value),
                          entry.x,
                          entry.y,
                          in_report_unit(entry, entry.face_value));
    return text;
  }

  std::string
  governing_lines(const std::vector<Compare::GoverningJoint> &governing)
  {
    std::string text;
    for (const auto &entry : governing)
      if (!entry.is_face_joint())
        text += fmt::format("governing: {} {} at {} (x = {:.3f} m, y = "
                            "{:.3f} m); the face joint {}\n",
                            entry.description,
                            in_report_unit(entry, entry.value),
                            entry.joint,
                            entry.x,
                            entry.y,
                            in_report_unit(entry, entry.face_value));
    if (text.empty() && !governing.empty())
      text = "governing: the face joint carries the largest Q and stresses\n";
    return text;
  }

  std::string
  governing_lift_plot(const Contact::SolveResult &result,
                      const unsigned int          n_blocks,
                      const double                floor_lift)
  {
    std::string data = "$g << EOD\n";
    bool        any  = false;
    for (const auto &increment : result.increments)
      if (increment.stage == Loading::LoadStage::uplift)
        {
          const auto governing = Compare::governing_joints(increment, n_blocks);
          const auto *averaged =
            find_figure(governing, "sigma_max_averaged_Pa");
          const auto *pointwise = find_figure(governing, "sigma_max_Pa");
          if (!averaged || !pointwise)
            continue;
          data += fmt::format("{} {} {} {} {}\n",
                              increment.stage_factor * floor_lift * 1e3,
                              averaged->face_value / MPa,
                              averaged->value / MPa,
                              pointwise->face_value / MPa,
                              pointwise->value / MPa);
          any = true;
        }
    if (!any)
      return "";
    return data + "EOD\n"
                  "set grid\nset key top left\nset xlabel 'base lift (mm)'\n"
                  "set ylabel 'peak normal stress (MPa)'\n"
                  "set title 'Peak stress along the floor lift: the face "
                  "joint and the largest over all joints'\n"
                  "plot $g using 1:2 with linespoints lc rgb 'blue' title "
                  "'face joint, averaged', $g using 1:3 with lines lw 2 dt 2 "
                  "lc rgb 'blue' title 'largest of all joints, averaged', "
                  "$g using 1:4 with linespoints lc rgb 'red' title 'face "
                  "joint, pointwise', $g using 1:5 with lines lw 2 dt 2 lc "
                  "rgb 'red' title 'largest of all joints, pointwise'\n";
  }
} // namespace FloorBlock::Output
