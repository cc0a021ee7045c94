#include <output/fem_error_estimate.h>
#include <output/json_values.h>

#include <utility>

namespace FloorBlock::Output
{
  using nlohmann::json;

  const char *
  reported_solve_name(const ReportedSolve solve)
  {
    return solve == ReportedSolve::coarse ? "coarse" : "refined";
  }

  namespace
  {
    json
    target_json(const AccuracyTarget &target)
    {
      json other_degrees = json::array();
      for (const AccuracyTarget &other : target.other_degrees)
        other_degrees.push_back(target_json(other));
      json levels = json::array();
      for (const RefinementLevelRecord &level : target.levels)
        levels.push_back(
          {{"level", level.level},
           {"n_cells", level.n_cells},
           {"n_dofs", level.n_dofs},
           {"wall_time_s", level.wall_time},
           {"status", level.status},
           {"face", level.face_figures},
           {"difference_indicator", optional_json(level.difference_indicator)},
           {"halved_n_dofs", level.halved_n_dofs},
           {"halved_wall_time_s", level.halved_wall_time},
           {"worst_target_relative_error",
            optional_json(level.worst_target_error)},
           {"halved_worst_target_relative_error",
            optional_json(level.halved_worst_target_error)}});
      return {{"relative_error", target.relative_error},
              {"figures", target.figures},
              {"met", target.met},
              {"reported_level", target.reported_level},
              {"reported_solve", reported_solve_name(target.reported_solve)},
              {"stop_reason", target.stop_reason},
              {"fe_degree", target.fe_degree},
              {"confirming_level",
               target.confirming_level ? json(*target.confirming_level) :
                                         json(nullptr)},
              {"fe_degree_choice", target.fe_degree_choice},
              {"other_fe_degrees", other_degrees},
              {"wall_time_s", target.wall_time},
              {"levels", levels}};
    }

    json
    figure_error_json(const FigureError &error)
    {
      return {{"value", error.value},
              {"coarse_value", error.coarse_value},
              {"refined_value", error.refined_value},
              {"absolute_error", error.absolute_error},
              {"relative_error", optional_json(error.relative_error)},
              {"oscillating", error.oscillating},
              {"next_level_value", optional_json(error.next_level_value)}};
    }
  } // namespace

  json
  fem_error_estimate_json(const FemErrorEstimate &estimate)
  {
    json result = {{"method", estimate.method}};
    if (estimate.target)
      result["target"] = target_json(*estimate.target);
    if (!estimate.available)
      {
        result["status"]      = "unavailable";
        result["status_text"] = estimate.status_text;
        return result;
      }
    const std::pair<const char *, FigureError JointErrors::*> figures[] = {
      {"normal_force_N_per_m", &JointErrors::normal_force},
      {"contact_length_m", &JointErrors::contact_length},
      {"sigma_max_Pa", &JointErrors::sigma_max},
      {"sigma_max_averaged_Pa", &JointErrors::sigma_max_averaged}};
    json joints = json::object();
    for (const auto &[name, errors] : estimate.joints)
      {
        json quantities = json::object();
        for (const auto &[key, member] : figures)
          quantities[key] = figure_error_json(errors.*member);
        joints[name] = quantities;
      }
    json corners = json::object();
    for (const auto &[name, errors] : estimate.corners)
      corners[name] = {
        {"safety_factor_point", figure_error_json(errors.point_factor)},
        {"safety_factor_line", figure_error_json(errors.line_factor)},
        {"safety_factor_area", figure_error_json(errors.area_factor)}};
    result["status"]         = "available";
    result["reported_solve"] = reported_solve_name(estimate.reported_solve);
    result["refined_n_dofs"] = estimate.refined_n_dofs;
    result["refined_status"] = estimate.refined_status;
    result["joints"]         = joints;
    result["corners"]        = corners;
    return result;
  }
} // namespace FloorBlock::Output
