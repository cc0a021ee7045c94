#include <output/floor_safety_lift.h>

#include <fmt/format.h>

namespace FloorBlock::Output
{
  using nlohmann::json;

  std::vector<LiftSafety>
  safety_along_lift(const std::vector<LiftHistoryPoint> &history)
  {
    std::vector<LiftSafety> along;
    for (const LiftHistoryPoint &point : history)
      {
        const Contact::CornerFactors *governing = nullptr;
        for (const Contact::CornerFactors &corner : point.corner_factors)
          if (corner.resolved &&
              (governing == nullptr ||
               corner.verdict_factor < governing->verdict_factor))
            governing = &corner;
        if (governing != nullptr)
          along.push_back({point.base_lift,
                           governing->corner,
                           governing->point_factor,
                           governing->line_factor,
                           governing->area_factor,
                           governing->verdict_factor,
                           governing->verdict_method});
      }
    return along;
  }

  std::optional<double>
  lift_at_unit_safety(const std::vector<LiftSafety> &along)
  {
    if (along.empty() || along.front().verdict_factor <= 1.)
      return std::nullopt;
    for (std::size_t k = 1; k < along.size(); ++k)
      if (along[k].verdict_factor <= 1.)
        {
          const LiftSafety &a = along[k - 1];
          const LiftSafety &b = along[k];
          const double      t =
            (a.verdict_factor - 1.) / (a.verdict_factor - b.verdict_factor);
          return a.base_lift + t * (b.base_lift - a.base_lift);
        }
    return std::nullopt;
  }

  std::string
  unit_safety_text(const std::vector<LiftSafety> &along)
  {
    if (along.empty())
      return "no increment of the lift resolves a corner's path";
    const std::string &method = along.front().verdict_method;
    if (const auto lift = lift_at_unit_safety(along))
      return fmt::format(
        "the governing corner's FS ({} method) reaches 1 at a floor lift "
        "of {:.2f} mm (between increments)",
        method,
        *lift * 1e3);
    if (along.front().verdict_factor <= 1.)
      return fmt::format(
        "FS ({} method) is below 1 from the lift's first increment on "
        "({:.3f} at {:.2f} mm): the floor fails before the lift, under the "
        "blocks' weight and the support load",
        method,
        along.front().verdict_factor,
        along.front().base_lift * 1e3);
    return fmt::format(
      "FS ({} method) stays above 1 over the lift ({:.3f} at its end)",
      method,
      along.back().verdict_factor);
  }

  json
  safety_along_lift_json(const std::vector<LiftSafety> &along)
  {
    json lifts   = json::array();
    json points  = json::array();
    json lines   = json::array();
    json areas   = json::array();
    json corners = json::array();
    for (const LiftSafety &entry : along)
      {
        lifts.push_back(entry.base_lift);
        points.push_back(entry.point_factor);
        lines.push_back(entry.line_factor);
        areas.push_back(entry.area_factor);
        corners.push_back(entry.corner);
      }
    json result = {{"lift_m", lifts},
                   {"governing_corner", corners},
                   {"safety_factor_point", points},
                   {"safety_factor_line", lines},
                   {"safety_factor_area", areas},
                   {"lift_at_safety_factor_1_text", unit_safety_text(along)}};
    if (!along.empty())
      result["verdict_method"] = along.front().verdict_method;
    if (const auto lift = lift_at_unit_safety(along))
      result["lift_at_safety_factor_1_m"] = *lift;
    return result;
  }

  std::string
  safety_along_lift_plot(const std::vector<LiftSafety> &along)
  {
    std::string data = "$s << EOD\n";
    for (const LiftSafety &entry : along)
      data += fmt::format("{} {} {} {}\n",
                          entry.base_lift * 1e3,
                          entry.point_factor,
                          entry.line_factor,
                          entry.area_factor);
    const std::string method =
      along.empty() ? std::string("line") : along.front().verdict_method;
    return data +
           fmt::format(
             "EOD\nset title 'Floor safety factor along the lift (governing "
             "corner; the verdict goes by the {} method)'\nset grid\nset key "
             "top right\nset xlabel 'base lift (mm)'\nset ylabel 'FS "
             "(Hoek-Brown, critical distance)'\nset yrange [0:*]\nplot $s "
             "using 1:2 with linespoints title 'point method (L/2)', $s using "
             "1:3 with linespoints title 'line method (mean over L)', $s using "
             "1:4 with linespoints title 'area method (mean within L)', 1 with "
             "lines dashtype 2 lc rgb 'red' title 'FS = 1'\n",
             method);
  }
} // namespace FloorBlock::Output
