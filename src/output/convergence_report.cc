#include <output/convergence_report.h>
#include <output/json_values.h>
#include <output/numbering_note.h>

#include <fmt/format.h>

#include <cctype>
#include <optional>
#include <set>

namespace FloorBlock::Output
{
  using nlohmann::json;
  using Refinement::Ladder;
  using Refinement::LevelRecord;
  using Refinement::Quantity;

  namespace
  {
    /** One colour per quantity (both modes), distinct for up to 12. */
    const std::vector<std::string> curve_colours = {"#1b9e77",
                                                    "#d95f02",
                                                    "#7570b3",
                                                    "#e7298a",
                                                    "#66a61e",
                                                    "#e6ab02",
                                                    "#a6761d",
                                                    "#666666",
                                                    "#1f78b4",
                                                    "#e31a1c",
                                                    "#000000",
                                                    "#b15928"};

    /** "Contact: linear solve" -> "wall_time_linear_solve_s". */
    std::string
    stage_column(const std::string &stage)
    {
      const std::string prefix = "Contact: ";
      std::string       name =
        stage.rfind(prefix, 0) == 0 ? stage.substr(prefix.size()) : stage;
      for (char &character : name)
        if (!std::isalnum(static_cast<unsigned char>(character)))
          character = '_';
      return "wall_time_" + name + "_s";
    }

    std::set<std::string>
    all_stages(const std::vector<Ladder> &ladders)
    {
      std::set<std::string> stages;
      for (const Ladder &ladder : ladders)
        for (const LevelRecord &record : ladder.levels)
          for (const auto &entry : record.stage_wall_times)
            stages.insert(entry.first);
      return stages;
    }

    std::string
    number(const std::optional<double> &value)
    {
      return value ? fmt::format("{:.9e}", *value) : std::string();
    }

    /** CSV field in double quotes (status texts contain commas). */
    std::string
    csv_field(const std::string &text)
    {
      std::string field = "\"";
      for (const char character : text)
        field +=
          character == '"' ? std::string("\"\"") : std::string(1, character);
      return field + "\"";
    }

    json
    optional_list(const std::vector<std::optional<double>> &values)
    {
      json list = json::array();
      for (const auto &value : values)
        list.push_back(optional_json(value));
      return list;
    }

    json
    level_json(const LevelRecord           &record,
               const std::vector<Quantity> &quantities)
    {
      json values = json::object();
      if (record.converged())
        for (const Quantity &quantity : quantities)
          values[quantity.name + "_" + quantity.unit] = quantity.value(record);
      return {{"level", record.level},
              {"status", record.status},
              {"status_text", record.status_text},
              {"converged", record.converged()},
              {"corner_size_m", record.corner_size},
              {"far_size_m", record.far_size},
              {"growth_rate", record.growth_rate},
              {"global_refinements", record.global_refinements},
              {"n_local_sizes", record.n_local_sizes},
              {"n_refinement_sweeps", record.n_refinement_sweeps},
              {"n_cells_coarsened", record.n_cells_coarsened},
              {"n_cells", record.n_cells},
              {"n_dofs", record.n_dofs},
              {"n_contact_pairs", record.n_contact_pairs},
              {"n_increments", record.n_increments},
              {"newton_iterations", record.newton_iterations},
              {"cutbacks", record.cutbacks},
              {"force_balance_relative_error", record.force_balance_error},
              {"wall_time_s_per_stage", record.stage_wall_times},
              {"wall_time_s", record.wall_time},
              {"cost_wall_time_s", record.cost_wall_time},
              {"quantities", values}};
    }
  } // namespace

  std::string
  convergence_csv(const std::vector<Ladder>   &ladders,
                  const std::vector<Quantity> &quantities)
  {
    const std::set<std::string> stages = all_stages(ladders);
    std::string                 csv    = fmt::format(
      "# {}\n# Q_face = Q_n (vertical joint n, next to the face block); "
                         "forces per metre of face.\n# cost_wall_time_s: wall time to obtain "
                         "the level from nothing (adaptive: all levels so far).\n# *_error_*: "
                         "estimated discretisation error; *_error_method: richardson or "
                         "finest_difference (see convergence.json for the reason).\n",
      numbering_note);
    csv +=
      "mode,level,status,converged,corner_size_m,far_size_m,growth_rate,"
      "global_refinements,n_local_sizes,n_refinement_sweeps,n_cells_coarsened,n_cells,n_dofs,"
      "n_contact_pairs,n_increments,"
      "newton_iterations,cutbacks,force_balance_relative_error";
    for (const std::string &stage : stages)
      csv += "," + stage_column(stage);
    csv += ",wall_time_s,cost_wall_time_s";
    for (const Quantity &quantity : quantities)
      csv += fmt::format(",{0}_{1},{0}_error_{1},{0}_relative_error,"
                         "{0}_error_method",
                         quantity.name,
                         quantity.unit);
    csv += ",status_text\n";

    for (const Ladder &ladder : ladders)
      for (std::size_t level = 0; level < ladder.levels.size(); ++level)
        {
          const LevelRecord &record = ladder.levels[level];
          csv += fmt::format(
            "{},{},{},{},{:.9e},{:.9e},{:.9e},{},{},{},{},{},{},{},{},{},{},{:.3e}",
            record.mode,
            record.level,
            record.status,
            record.converged() ? "true" : "false",
            record.corner_size,
            record.far_size,
            record.growth_rate,
            record.global_refinements,
            record.n_local_sizes,
            record.n_refinement_sweeps,
            record.n_cells_coarsened,
            record.n_cells,
            record.n_dofs,
            record.n_contact_pairs,
            record.n_increments,
            record.newton_iterations,
            record.cutbacks,
            record.force_balance_error);
          for (const std::string &stage : stages)
            {
              const auto found = record.stage_wall_times.find(stage);
              csv += "," + (found == record.stage_wall_times.end() ?
                              std::string() :
                              fmt::format("{:.4f}", found->second));
            }
          csv += fmt::format(",{:.4f},{:.4f}",
                             record.wall_time,
                             record.cost_wall_time);
          for (std::size_t q = 0; q < quantities.size(); ++q)
            {
              const auto &errors = ladder.errors.at(q);
              csv +=
                "," +
                number(record.converged() ?
                         std::optional<double>(quantities[q].value(record)) :
                         std::nullopt);
              csv += "," + number(errors.errors.at(level));
              csv += "," + number(errors.relative_errors.at(level));
              csv += "," + Refinement::method_name(errors.method);
            }
          csv += "," + csv_field(record.status_text) + "\n";
        }
    return csv;
  }

  json
  convergence_json(
    const std::vector<Ladder>                           &ladders,
    const std::vector<Quantity>                         &quantities,
    const std::vector<Refinement::EqualErrorComparison> &comparisons)
  {
    json modes = json::object();
    for (const Ladder &ladder : ladders)
      {
        json levels = json::array();
        for (const LevelRecord &record : ladder.levels)
          levels.push_back(level_json(record, quantities));
        json estimates = json::object();
        for (std::size_t q = 0; q < quantities.size(); ++q)
          {
            const auto &errors            = ladder.errors.at(q);
            estimates[quantities[q].name] = {
              {"unit", quantities[q].unit},
              {"method", Refinement::method_name(errors.method)},
              {"reason", errors.reason},
              {"observed_orders", optional_list(errors.observed_orders)},
              {"reference_value", optional_json(errors.reference)},
              {"errors", optional_list(errors.errors)},
              {"relative_errors", optional_list(errors.relative_errors)}};
          }
        modes[ladder.mode] = {{"levels", levels},
                              {"quantities", estimates},
                              {"stopped_because", ladder.stopped_because}};
      }

    json equal_error = json::array();
    for (const auto &comparison : comparisons)
      {
        const auto level = [](const std::optional<unsigned int> &value) {
          return value ? json(*value) : json(nullptr);
        };
        equal_error.push_back(
          {{"quantity", comparison.quantity},
           {"mode", comparison.adaptive_mode},
           {"target_relative_error", comparison.target_relative_error},
           {"uniform_level", level(comparison.uniform_level)},
           {"adaptive_level", level(comparison.adaptive_level)},
           {"dofs_ratio_adaptive_over_uniform",
            optional_json(comparison.dofs_ratio)},
           {"cost_wall_time_ratio_adaptive_over_uniform",
            optional_json(comparison.cost_ratio)},
           {"ratios_are_upper_bounds", comparison.ratios_are_upper_bounds},
           {"reference_difference_relative",
            optional_json(comparison.reference_difference)}});
      }
    return {{"numbering", numbering_note},
            {"equal_error_rule",
             "per ladder, the first level from which on every finer level's "
             "own estimated relative error is within the target; "
             "reference_difference_relative compares the two ladders' best "
             "values (an equal-error comparison only if it is within the "
             "target too)"},
            {"observed_order",
             "p_l = log2(|q_{l-1} - q_{l-2}| / |q_l - q_{l-1}|), per level "
             "halving of the element size (adaptive: of the requested "
             "sizes where refined)"},
            {"modes", modes},
            {"equal_error_comparison", equal_error}};
  }

  std::string
  error_vs_time_plot(const std::vector<Ladder>   &ladders,
                     const std::vector<Quantity> &quantities,
                     const std::string           &title)
  {
    std::string script =
      fmt::format("set title '{}'\nset logscale xy\nset format y '%.0e'\n"
                  "set xlabel 'wall time to obtain the level (s)'\n"
                  "set ylabel 'estimated relative error'\nset grid\n"
                  "set key outside right top\n",
                  title);
    std::string  plot  = "plot ";
    unsigned int block = 0;
    for (const Ladder &ladder : ladders)
      for (std::size_t q = 0; q < quantities.size(); ++q)
        {
          std::string rows;
          for (std::size_t level = 0; level < ladder.levels.size(); ++level)
            {
              const auto &relative =
                ladder.errors.at(q).relative_errors.at(level);
              // Round-off differences are no discretisation error.
              if (relative && *relative > Refinement::round_off_level &&
                  ladder.levels[level].cost_wall_time > 0.)
                rows += fmt::format("{:.6e} {:.6e}\n",
                                    ladder.levels[level].cost_wall_time,
                                    *relative);
            }
          if (rows.empty())
            continue;
          script += fmt::format("$d{} << EOD\n{}EOD\n", block, rows);
          plot += fmt::format(
            "{}$d{} with linespoints lc rgb '{}' dt {} pt {} title '{} {}'",
            plot == "plot " ? "" : ", ",
            block,
            curve_colours[q % curve_colours.size()],
            ladder.mode == "uniform" ? 1 : (ladder.mode == "adaptive" ? 2 : 3),
            ladder.mode == "uniform" ? 7 : (ladder.mode == "adaptive" ? 6 : 4),
            ladder.mode,
            quantities[q].name);
          ++block;
        }
    if (block == 0)
      return script + "set label 'no error estimates' at graph 0.4,0.5\n"
                      "unset logscale\nplot [0:1][0:1] NaN notitle\n";
    return script + plot + "\n";
  }

  std::string
  TargetVerdict::status() const
  {
    if (!evaluated)
      return "not evaluated";
    return met ? "met" : "not met";
  }

  json
  target_verdict_json(const TargetVerdict &verdict)
  {
    if (!verdict.evaluated)
      return {{"status", verdict.status()}, {"text", verdict.text}};
    return {{"status", verdict.status()},
            {"text", verdict.text},
            {"dofs_ratio_limit", verdict.dofs_ratio_limit},
            {"cost_ratio_limit", verdict.cost_ratio_limit}};
  }

  json
  convergence_study_json(
    const std::vector<Refinement::Ladder>               &ladders,
    const std::vector<Refinement::Quantity>             &quantities,
    const std::vector<Refinement::EqualErrorComparison> &comparisons,
    const TargetVerdict                                 &adaptive_target,
    const std::optional<TargetVerdict>                  &remesh_target)
  {
    json report = convergence_json(ladders, quantities, comparisons);
    report["adaptive_target"] = target_verdict_json(adaptive_target);
    if (remesh_target)
      report["remesh_target"] = target_verdict_json(*remesh_target);
    return report;
  }

  json
  convergence_summary_json(const std::string   &scene_name,
                           const bool           all_converged,
                           const TargetVerdict &adaptive_target,
                           const double         wall_time)
  {
    return {{"scene", scene_name},
            {"status",
             all_converged ? "converged" : "not every level converged"},
            {"adaptive_target", target_verdict_json(adaptive_target)},
            {"wall_time_s", wall_time}};
  }

  std::string
  ladder_text(const Refinement::Ladder                &ladder,
              const std::vector<Refinement::Quantity> &quantities)
  {
    std::string text = fmt::format("{} refinement:\n", ladder.mode);
    if (!ladder.stopped_because.empty())
      text += fmt::format("  (ladder {})\n", ladder.stopped_because);
    for (std::size_t q = 0; q < quantities.size(); ++q)
      {
        const auto &errors = ladder.errors[q];
        // The order used by the extrapolation; all orders are in the JSON.
        std::string order = "-";
        if (errors.method == Refinement::ErrorMethod::richardson)
          for (const auto &observed : errors.observed_orders)
            if (observed)
              order = fmt::format("{:.2f}", *observed);
        text += fmt::format("  {:<26} {:<18} order {:>6}  ref {:>13}  ({})\n",
                            quantities[q].name,
                            Refinement::method_name(errors.method),
                            order,
                            errors.reference ?
                              fmt::format("{:.6e}", *errors.reference) :
                              std::string("-"),
                            errors.reason);
      }
    return text;
  }
} // namespace FloorBlock::Output
