#include <common/units.h>
#include <output/floor_safety_report.h>

#include <fmt/format.h>

namespace FloorBlock::Output
{
  using nlohmann::json;

  namespace
  {
    const char *
    verdict(const double factor)
    {
      return factor < 1. ? "the corner fails" : "the corner holds";
    }

    std::string
    unresolved_text(const Safety::CornerSafety &corner)
    {
      return fmt::format(
        "not evaluated: cells of up to {:.1f} mm along the corner paths "
        "against a critical distance L = {:.1f} mm (at most L/{:.0f} "
        "needed); set Mesh/Cells per critical distance, e.g. to 16, and "
        "where the corner cells stay larger, Mesh/Global refinements = 1",
        corner.largest_cell * 1e3,
        corner.critical_distance * 1e3,
        Safety::min_cells_per_critical_distance);
    }
  } // namespace

  json
  floor_safety_json(const std::vector<Safety::CornerSafety> &corners)
  {
    if (corners.empty())
      return nullptr;
    json records = json::array();
    for (const Safety::CornerSafety &corner : corners)
      records.push_back(
        {{"joint", corner.path.joint_name},
         {"block", corner.path.block},
         {"hot_spot_m", {corner.path.start.x, corner.path.start.y}},
         {"path_direction", {corner.path.direction.x, corner.path.direction.y}},
         {"safety_factor_point", corner.point_factor},
         {"safety_factor_line", corner.line_factor},
         {"safety_factor_area", corner.area_factor},
         {"sigma_1_at_half_L_Pa", corner.point_stresses.sigma_1},
         {"sigma_3_at_half_L_Pa", corner.point_stresses.sigma_3},
         {"sigma_1_mean_over_L_Pa", corner.line_stresses.sigma_1},
         {"sigma_3_mean_over_L_Pa", corner.line_stresses.sigma_3},
         {"sigma_1_mean_within_L_Pa", corner.area_stresses.sigma_1},
         {"sigma_3_mean_within_L_Pa", corner.area_stresses.sigma_3},
         {"largest_cell_m", corner.largest_cell},
         {"largest_cell_within_L_m", corner.largest_cell_within_L},
         {"resolved", corner.resolved()}});
    const Safety::CornerSafety &governing = Safety::governing_corner(corners);
    if (!governing.resolved())
      return {{"critical_distance_m", governing.critical_distance},
              {"status", "unresolved"},
              {"status_text", unresolved_text(governing)},
              {"corners", records}};
    return {
      {"critical_distance_m", governing.critical_distance},
      {"method_text",
       "Hoek-Brown strength factor (the factor by which the stress state, "
       "compression positive, can be scaled before it reaches the "
       "envelope) of the stress at L/2 (point method) and of the mean "
       "stress over L (line method) along the inward bisector of each "
       "floor-level block corner from its surface point, and of the mean "
       "stress over the block within L of that point (area method); the "
       "verdict and the governing corner go by verdict_method: the line "
       "method with compliant joints, the area method with exact contact "
       "(src/safety/)"},
      {"corners", records},
      {"governing",
       {{"joint", governing.path.joint_name},
        {"block", governing.path.block},
        {"safety_factor_point", governing.point_factor},
        {"safety_factor_line", governing.line_factor},
        {"safety_factor_area", governing.area_factor},
        {"verdict_method", Safety::to_string(governing.verdict_method)},
        {"status",
         Safety::verdict_factor(governing) < 1. ? "fails" : "holds"}}}};
  }

  std::string
  floor_safety_text(const std::vector<Safety::CornerSafety> &corners)
  {
    if (corners.empty())
      return {};
    const Safety::CornerSafety &governing = Safety::governing_corner(corners);
    if (!governing.resolved())
      return "  floor safety: " + unresolved_text(governing) + "\n";
    return fmt::format(
      "  floor safety (Hoek-Brown, critical distance L = {:.1f} mm): "
      "governing corner {} at {}: FS = {:.2f} ({} method, the verdict); "
      "point {:.2f}, line {:.2f}, area {:.2f}: {}\n",
      governing.critical_distance * 1e3,
      governing.path.block,
      governing.path.joint_name,
      Safety::verdict_factor(governing),
      Safety::to_string(governing.verdict_method),
      governing.point_factor,
      governing.line_factor,
      governing.area_factor,
      verdict(Safety::verdict_factor(governing)));
  }

  std::string
  floor_safety_paths_csv(const std::vector<Safety::CornerSafety> &corners)
  {
    std::string csv = "# Stresses along the floor safety factor's corner "
                      "paths (src/safety/), compression positive\n"
                      "joint,block,distance_m,sigma_1_Pa,sigma_3_Pa,"
                      "strength_factor\n";
    for (const Safety::CornerSafety &corner : corners)
      // An unresolved path has samples but no factors
      // (Safety::corner_safety()): its stresses are single cells' values.
      if (corner.sample_factors.size() == corner.samples.size())
        for (std::size_t k = 0; k < corner.samples.size(); ++k)
          {
            const Strength::PathSample       &sample = corner.samples[k];
            const Strength::PrincipalStresses principal =
              Strength::principal_stresses(sample.stress);
            csv += fmt::format("{},{},{:.9e},{:.9e},{:.9e},{:.9e}\n",
                               corner.path.joint_name,
                               corner.path.block,
                               sample.distance,
                               principal.sigma_1,
                               principal.sigma_3,
                               corner.sample_factors[k]);
          }
    return csv;
  }
} // namespace FloorBlock::Output
