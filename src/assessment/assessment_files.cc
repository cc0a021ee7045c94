#include <assessment/assessment_files.h>
#include <fmt/format.h>

#include <algorithm>

namespace FloorBlock::Assessment
{
  namespace
  {
    nlohmann::json
    indices_json(const AssessmentResult &result,
                 const OT::Point        &indices,
                 const OT::Interval     &interval)
    {
      nlohmann::json json = nlohmann::json::object();
      for (std::size_t i = 0; i < result.inputs.size(); ++i)
        json[result.inputs[i].path] = {{"index", indices[i]},
                                       {"interval_95",
                                        {interval.getLowerBound()[i],
                                         interval.getUpperBound()[i]}}};
      return json;
    }

    nlohmann::json
    case_counts(const std::vector<SafetyCase> &cases)
    {
      nlohmann::json counts = {{"total", cases.size()},
                               {"solved", 0},
                               {"not_converged", 0},
                               {"failed", 0},
                               {"refused", 0}};
      for (const SafetyCase &c : cases)
        {
          const std::string key =
            c.status == "not converged" ? "not_converged" : c.status;
          counts[key] = counts[key].get<int>() + 1;
        }
      return counts;
    }

    /** A CSV field: quoted when it holds a comma or a quote. */
    std::string
    field(const std::string &text)
    {
      if (text.find_first_of(",\"\n") == std::string::npos)
        return text;
      std::string quoted = "\"";
      for (const char c : text)
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
      return quoted + "\"";
    }
  } // namespace

  std::string
  input_column(const Parameters::UncertainInput &input)
  {
    return input.path + " (" + input.unit + ")";
  }

  nlohmann::json
  assessment_json(const AssessmentResult &result)
  {
    nlohmann::json inputs = nlohmann::json::array();
    for (const auto &input : result.inputs)
      inputs.push_back(
        {{"path", input.path},
         {"unit", input.unit},
         {"distribution", input.text.substr(input.text.rfind(':') + 1)}});
    nlohmann::json correlations = nlohmann::json::array();
    for (const auto &c : result.correlations)
      correlations.push_back({{"first", c.first},
                              {"second", c.second},
                              {"gaussian_copula", c.value}});

    const auto    &mc           = result.failure.monte_carlo;
    nlohmann::json design_point = nlohmann::json::object();
    for (std::size_t i = 0; i < result.inputs.size(); ++i)
      design_point[input_column(result.inputs[i])] =
        result.design_point.point[i];

    nlohmann::json costs = nlohmann::json::array();
    for (const ModelCost &cost : result.costs)
      costs.push_back({{"model", cost.model},
                       {"evaluations", cost.evaluations},
                       {"from_earlier_runs", cost.from_earlier_runs},
                       {"wall_time_s", cost.wall_time}});

    const auto    &s     = result.surrogate;
    nlohmann::json limit = nullptr;
    if (result.design_limit)
      {
        const DesignLimit &d = *result.design_limit;
        limit                = {{"input", input_column(result.inputs[d.input])},
                                {"range", {d.values.front(), d.values.back()}},
                                {"range_is", "the input's 1 % to 99 % quantiles"},
                                {"model", "surrogate"},
                                {"file", "design_limit.csv"}};
        nlohmann::json limits = nlohmann::json::array();
        for (const auto &[target, value] : d.limits)
          limits.push_back(
            value ? nlohmann::json{{"P_FS_below_1", target},
                                   {"value", *value},
                                   {"status", "reached"}} :
                    nlohmann::json{{"P_FS_below_1", target},
                                   {"value", nullptr},
                                   {"status", "not reached within the range"}});
        limit["limits"] = limits;
      }
    return {{"status", "complete"},
            {"question",
             "P(FS < 1): the probability that the governing floor "
             "corner's safety factor (the verdict's method) is below 1"},
            {"inputs", inputs},
            {"correlations", correlations},
            {"failure_probability",
             {{"estimate", mc.probability},
              {"half_width_95", mc.half_width},
              {"interval_95",
               {std::max(0., mc.probability - mc.half_width),
                std::min(1., mc.probability + mc.half_width)}},
              {"evaluations", mc.evaluations},
              {"model", "surrogate"},
              {"with_surrogate_error",
               {{"stated_error_of_ln_FS", s.stated_error},
                {"P_FS_times_exp_error_below_1",
                 result.failure.lower_with_surrogate_error},
                {"P_FS_over_exp_error_below_1",
                 result.failure.upper_with_surrogate_error}}}}},
            {"form",
             {{"reliability_index", result.design_point.reliability_index},
              {"probability", result.design_point.probability},
              {"design_point", design_point},
              {"model", "surrogate"}}},
            {"sobol_indices",
             {{"first_order",
               indices_json(result,
                            result.sobol.first_order,
                            result.sobol.first_order_interval)},
              {"total_order",
               indices_json(result,
                            result.sobol.total_order,
                            result.sobol.total_order_interval)},
              {"evaluations", result.sobol.evaluations},
              {"assumption",
               "the inputs' marginals taken independent (Saltelli "
               "estimators, bootstrap intervals, on the surrogate)"}}},
            {"surrogate",
             {{"output",
               "ln FS; errors are of ln FS, a factor exp(error) on FS"},
              {"kind", s.kind},
              {"chosen_among",
               "sparse polynomial chaos of each degree from 1, and kriging, by "
               "the smallest cross-validation rms"},
              {"cross_validation_rms", s.cross_validation_rms},
              {"cross_validation_folds", s.n_folds},
              {"stated_error_meaning",
               "95 % split-conformal bound of the cross-validation "
               "residuals: a new case drawn like the training cases lies "
               "within it with probability at least 0.95"},
              {"stated_error", s.stated_error},
              {"held_out",
               {{"cases", result.held_out.n_points},
                {"rms", result.held_out.rms},
                {"largest", result.held_out.largest},
                {"share_within_stated_error",
                 result.held_out.share_within_stated}}}}},
            {"design_limit", limit},
            {"fem_cases",
             {{"training", case_counts(result.training)},
              {"validation", case_counts(result.validation)}}},
            {"cost_by_model", costs}};
  }

  std::string
  design_limit_csv(const AssessmentResult &result)
  {
    const DesignLimit &d   = result.design_limit.value();
    std::string        csv = field(input_column(result.inputs[d.input])) +
                      ",P_FS_below_1,half_width_95\n";
    for (std::size_t k = 0; k < d.values.size(); ++k)
      csv += fmt::format("{},{},{}\n",
                         d.values[k],
                         d.probabilities[k].probability,
                         d.probabilities[k].half_width);
    return csv;
  }

  std::string
  cases_csv(const AssessmentResult &result)
  {
    std::string csv = "id,role,model,status";
    for (const auto &input : result.inputs)
      csv += "," + field(input_column(input));
    csv += ",FS,FS_point,FS_line,FS_area,verdict_method,governing_corner,"
           "FS_surrogate,n_dofs,wall_time_s,message\n";
    const auto rows = [&](const std::vector<SafetyCase> &cases,
                          const std::vector<double>     &surrogate,
                          const std::string             &role) {
      for (std::size_t k = 0; k < cases.size(); ++k)
        {
          const SafetyCase &c = cases[k];
          // Training cases are of the Latin hypercube or of a refinement
          // round: the id's prefix says which.
          csv += c.id + "," +
                 (role == "training" ? c.id.substr(0, c.id.find('_')) : role) +
                 ",fem," + field(c.status);
          for (const double value : c.inputs)
            csv += fmt::format(",{}", value);
          if (c.solved())
            csv += fmt::format(",{},{},{},{},{},{}",
                               c.safety_factor,
                               c.point_factor,
                               c.line_factor,
                               c.area_factor,
                               c.verdict_method,
                               field(c.governing_corner));
          else
            csv += ",,,,,,";
          csv += fmt::format(",{},{},{},{}\n",
                             surrogate.at(k),
                             c.n_dofs,
                             c.wall_time,
                             field(c.message));
        }
    };
    rows(result.training, result.surrogate_at_training, "training");
    rows(result.validation, result.surrogate_at_validation, "validation");
    return csv;
  }
} // namespace FloorBlock::Assessment
