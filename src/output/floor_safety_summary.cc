#include <common/units.h>
#include <output/floor_safety_summary.h>
#include <output/json_values.h>

#include <fmt/format.h>

namespace FloorBlock::Output
{
  using nlohmann::json;

  namespace
  {
    /** The estimate of @p corner's factors, if there is one. */
    const CornerErrors *
    errors_of(const Safety::CornerSafety            &corner,
              const std::optional<FemErrorEstimate> &estimate)
    {
      if (!estimate || !estimate->available)
        return nullptr;
      const auto found = estimate->corners.find(corner.path.label());
      return found == estimate->corners.end() ? nullptr : &found->second;
    }

    /** Why a corner's factor has no error estimate, in words. */
    std::string
    error_status(const Safety::CornerSafety            &corner,
                 const std::optional<FemErrorEstimate> &estimate)
    {
      if (errors_of(corner, estimate) != nullptr)
        return "estimated";
      if (!estimate)
        return "error not estimated: no refined solve was made";
      if (!estimate->available)
        return "error not estimated: " + estimate->status_text;
      return "error not estimated: the refined solve does not resolve the "
             "corner's path";
    }

    json
    corner_json(const Safety::CornerSafety            &corner,
                const std::optional<FemErrorEstimate> &estimate)
    {
      const CornerErrors *errors = errors_of(corner, estimate);
      return {{"corner", corner.path.label()},
              {"resolved", corner.resolved()},
              {"safety_factor_point", corner.point_factor},
              {"safety_factor_point_relative_error",
               errors ? optional_json(errors->point_factor.relative_error) :
                        json(nullptr)},
              {"safety_factor_line", corner.line_factor},
              {"safety_factor_line_relative_error",
               errors ? optional_json(errors->line_factor.relative_error) :
                        json(nullptr)},
              {"safety_factor_area", corner.area_factor},
              {"safety_factor_area_relative_error",
               errors ? optional_json(errors->area_factor.relative_error) :
                        json(nullptr)},
              // The errors are null where not estimated; status says why.
              {"status", error_status(corner, estimate)}};
    }

    json
    chapter_route_json(const Scene::ClosedForms &closed_forms)
    {
      json factors = json::object();
      for (const Scene::MechanismResult &entry : closed_forms.mechanisms)
        if (entry.floor_safety_factor)
          factors[Scene::to_string(entry.mechanism)] =
            *entry.floor_safety_factor;
      return factors;
    }

    /** "+- 1.2 %" or "(error not estimated)". */
    std::string
    error_text(const CornerErrors *errors, FigureError CornerErrors::*figure)
    {
      if (errors == nullptr || !(errors->*figure).relative_error)
        return "(error not estimated)";
      return fmt::format("+- {:.2g} %",
                         100. * *(errors->*figure).relative_error);
    }

    /** A factor and its error as two cells of report.md's table. At the
     * cap (an almost unloaded corner) the factor only says "at least" and
     * an error of it says nothing. */
    std::string
    factor_cells(const double        factor,
                 const CornerErrors *errors,
                 FigureError CornerErrors::*figure)
    {
      if (factor >= Strength::largest_strength_factor)
        return fmt::format(">= {:.0f} (almost unloaded) | |",
                           Strength::largest_strength_factor);
      return fmt::format("{:.3f} | {}", factor, error_text(errors, figure));
    }

    std::string
    chapter_route_text(const Scene::ClosedForms &closed_forms)
    {
      std::string text;
      for (const Scene::MechanismResult &entry : closed_forms.mechanisms)
        if (entry.floor_safety_factor)
          text += fmt::format("{}{} {:.2f}",
                              text.empty() ? "" : ", ",
                              Scene::to_string(entry.mechanism),
                              *entry.floor_safety_factor);
      return text.empty() ?
               std::string("no mechanism gives Eq. 6.53 an answer") :
               text;
    }
  } // namespace

  json
  floor_safety_summary_json(const std::vector<Safety::CornerSafety> &corners,
                            const std::optional<FemErrorEstimate>   &estimate,
                            const Scene::ClosedForms &closed_forms)
  {
    json summary = {{"floor_strength_Pa", closed_forms.floor_strength},
                    {"safety_factor_eq_6_53",
                     chapter_route_json(closed_forms)}};
    if (corners.empty())
      {
        summary["status"] = "not evaluated";
        summary["status_text"] =
          "the FEM gave no corner stresses (a 2D elastic "
          "FEM solve with a converged increment does)";
        return summary;
      }
    json records = json::array();
    for (const Safety::CornerSafety &corner : corners)
      records.push_back(corner_json(corner, estimate));
    const Safety::CornerSafety &governing = Safety::governing_corner(corners);
    summary["critical_distance_m"]        = governing.critical_distance;
    summary["corners"]                    = records;
    if (!governing.resolved())
      {
        summary["status"] = "unresolved";
        summary["status_text"] =
          "the mesh does not resolve the critical distance along every "
          "corner path (" +
          governing.path.label() + " has cells of " +
          fmt::format("{:.1f}", governing.largest_cell * 1e3) +
          " mm); set Mesh/Cells per critical distance, or Mesh/Global "
          "refinements where the corner cells stay larger";
        return summary;
      }
    summary["governing"]      = corner_json(governing, estimate);
    summary["verdict_method"] = Safety::to_string(governing.verdict_method);
    summary["status"] =
      Safety::verdict_factor(governing) < 1. ? "fails" : "holds";
    return summary;
  }

  std::string
  floor_safety_summary_lines(const std::vector<Safety::CornerSafety> &corners,
                             const std::optional<FemErrorEstimate>   &estimate,
                             const Scene::ClosedForms &closed_forms)
  {
    const std::string route =
      fmt::format("  floor safety by the chapter's route (sigma_c = {:.2f} MPa "
                  "over Eq. 6.53's sigma_max): {}\n",
                  closed_forms.floor_strength / Units::MPa,
                  chapter_route_text(closed_forms));
    if (corners.empty() || !Safety::governing_corner(corners).resolved())
      return route;
    const Safety::CornerSafety &governing = Safety::governing_corner(corners);
    const CornerErrors         *errors    = errors_of(governing, estimate);
    return fmt::format(
             "  floor safety at the governing corner ({}, L = {:.1f} mm): "
             "FS = {:.3f} {} (point method), {:.3f} {} (line method), {:.3f} "
             "{} (area method); the verdict goes by the {} method: {}\n",
             governing.path.label(),
             governing.critical_distance * 1e3,
             governing.point_factor,
             error_text(errors, &CornerErrors::point_factor),
             governing.line_factor,
             error_text(errors, &CornerErrors::line_factor),
             governing.area_factor,
             error_text(errors, &CornerErrors::area_factor),
             Safety::to_string(governing.verdict_method),
             Safety::verdict_factor(governing) < 1. ? "the corner fails" :
                                                      "the corner holds") +
           route;
  }

  std::string
  floor_safety_markdown(const std::vector<Safety::CornerSafety> &corners,
                        const std::optional<FemErrorEstimate>   &estimate,
                        const Scene::ClosedForms                &closed_forms)
  {
    std::string text = fmt::format(
      "The chapter's route: the rock mass's uniaxial strength sigma_c = "
      "{:.2f} MPa (generalised Hoek-Brown, Strength/) over Eq. 6.53's "
      "sigma_max at the face: FS = {}.\n\n",
      closed_forms.floor_strength / Units::MPa,
      chapter_route_text(closed_forms));
    if (corners.empty())
      return text + "The FEM gave no corner stresses.\n";
    text += fmt::format(
      "The FEM's route: the Hoek-Brown strength factor of the stress at L/2 "
      "(point method) and of its mean over L (line method) along each "
      "floor-level corner's bisector, and of the mean stress over the block "
      "within L of the corner (area method), L = {:.1f} mm (src/safety/); "
      "the verdict goes by the {} method.\n\n"
      "| corner | FS point | error | FS line | error | FS area | error |\n"
      "|---|---|---|---|---|---|---|\n",
      corners.front().critical_distance * 1e3,
      Safety::to_string(corners.front().verdict_method));
    for (const Safety::CornerSafety &corner : corners)
      {
        const CornerErrors *errors = errors_of(corner, estimate);
        text +=
          corner.resolved() ?
            fmt::format("| {} | {} | {} | {} |\n",
                        corner.path.label(),
                        factor_cells(corner.point_factor,
                                     errors,
                                     &CornerErrors::point_factor),
                        factor_cells(corner.line_factor,
                                     errors,
                                     &CornerErrors::line_factor),
                        factor_cells(corner.area_factor,
                                     errors,
                                     &CornerErrors::area_factor)) :
            fmt::format("| {} | unresolved (cells of {:.1f} mm) | | | | | |\n",
                        corner.path.label(),
                        corner.largest_cell * 1e3);
      }
    return text;
  }
} // namespace FloorBlock::Output
