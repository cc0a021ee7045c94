#include <common/input_error.h>
#include <parameters/scenario_parameters.h>
#include <parameters/value_text.h>
#include <pipeline/fem_pipeline.h>
#include <pipeline/scratch_folder.h>

#include <deal.II/base/timer.h>

#include <assessment/safety_case.h>

#include <algorithm>

namespace FloorBlock::Assessment
{
  std::vector<std::string>
  input_overrides(const SceneSource &source, const std::vector<double> &values)
  {
    std::vector<std::string> overrides = source.overrides;
    for (std::size_t i = 0; i < source.inputs.size(); ++i)
      overrides.push_back(source.inputs[i].path + "=" +
                          Parameters::number(values.at(i)));
    return overrides;
  }

  SafetyCase
  solve_safety_case(const SceneSource         &source,
                    const std::string         &id,
                    const std::vector<double> &values)
  {
    dealii::Timer timer;
    SafetyCase    result;
    result.id     = id;
    result.inputs = values;

    Parameters::ScenarioParameters scene;
    try
      {
        scene = Parameters::read_scenario(source.path,
                                          input_overrides(source, values));
      }
    catch (const InputError &error)
      {
        result.status    = "refused";
        result.message   = error.what();
        result.wall_time = timer.wall_time();
        return result;
      }

    const Pipeline::ScratchFolder scratch(id);
    Pipeline::FemOutcome          outcome;
    try
      {
        outcome =
          Pipeline::solve_scene(scene,
                                Output::ResultFolder(scratch.path.string()),
                                false);
      }
    catch (const std::exception &error)
      {
        // The mesher or a solver gave up on this draw (not a cutback's
        // failure, which solve_scene reports): the case says so and the
        // study goes on without it.
        result.status    = "failed";
        result.message   = error.what();
        result.wall_time = timer.wall_time();
        return result;
      }
    result.n_dofs          = outcome.result.n_dofs;
    const auto &increments = outcome.result.increments;
    if (!outcome.converged || increments.empty() ||
        increments.back().corner_factors.empty())
      {
        result.status  = "not converged";
        result.message = outcome.converged ?
                           "no corner safety factors (not a 2D elastic solve)" :
                           "the contact solve failed after its cutbacks";
      }
    else
      {
        const auto &factors = increments.back().corner_factors;
        const auto  governing =
          std::min_element(factors.begin(),
                           factors.end(),
                           [](const auto &a, const auto &b) {
                             return a.verdict_factor < b.verdict_factor;
                           });
        result.status           = "solved";
        result.safety_factor    = governing->verdict_factor;
        result.point_factor     = governing->point_factor;
        result.line_factor      = governing->line_factor;
        result.area_factor      = governing->area_factor;
        result.verdict_method   = governing->verdict_method;
        result.governing_corner = governing->corner;
      }
    result.wall_time = timer.wall_time();
    return result;
  }

  nlohmann::json
  to_json(const SafetyCase &c)
  {
    nlohmann::json json = {{"id", c.id},
                           {"inputs", c.inputs},
                           {"status", c.status},
                           {"message", c.message},
                           {"n_dofs", c.n_dofs},
                           {"wall_time_s", c.wall_time}};
    if (c.solved())
      {
        json["safety_factor"]    = c.safety_factor;
        json["point_factor"]     = c.point_factor;
        json["line_factor"]      = c.line_factor;
        json["area_factor"]      = c.area_factor;
        json["verdict_method"]   = c.verdict_method;
        json["governing_corner"] = c.governing_corner;
      }
    return json;
  }

  SafetyCase
  safety_case_from_json(const nlohmann::json &json)
  {
    SafetyCase c;
    try
      {
        c.id        = json.at("id").get<std::string>();
        c.inputs    = json.at("inputs").get<std::vector<double>>();
        c.status    = json.at("status").get<std::string>();
        c.message   = json.at("message").get<std::string>();
        c.n_dofs    = json.at("n_dofs").get<unsigned int>();
        c.wall_time = json.at("wall_time_s").get<double>();
        if (c.solved())
          {
            c.safety_factor    = json.at("safety_factor").get<double>();
            c.point_factor     = json.at("point_factor").get<double>();
            c.line_factor      = json.at("line_factor").get<double>();
            c.area_factor      = json.at("area_factor").get<double>();
            c.verdict_method   = json.at("verdict_method").get<std::string>();
            c.governing_corner = json.at("governing_corner").get<std::string>();
          }
      }
    catch (const nlohmann::json::exception &error)
      {
        throw std::runtime_error("assessment case record: " +
                                 std::string(error.what()));
      }
    return c;
  }
} // namespace FloorBlock::Assessment
