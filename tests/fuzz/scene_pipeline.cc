#include "scene_pipeline.h"

#include <common/input_error.h>
#include <output/analytic_report.h>
#include <parameters/scenario_parameters.h>
#include <scene/closed_forms.h>

#include <fstream>

#include "output_checks.h"

namespace FloorBlock::Fuzz
{
  namespace
  {
    std::filesystem::path
    write_file(const std::filesystem::path &path, const std::string &text)
    {
      std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
      return path;
    }

    void
    append(std::vector<std::string>       &defects,
           const std::vector<std::string> &more,
           const std::string              &prefix)
    {
      for (const std::string &defect : more)
        defects.push_back(prefix + defect);
    }

    /** The scene's analytic.json, checking every output on the way. */
    nlohmann::json
    checked_report(const Parameters::ScenarioParameters &scene,
                   std::vector<std::string>             &defects)
    {
      const Scene::ClosedForms closed_forms =
        Scene::evaluate_closed_forms(scene);
      append(defects, closed_form_defects(closed_forms), "closed forms: ");
      const nlohmann::json report = Output::analytic_json(closed_forms);
      append(defects, json_defects(report), "analytic.json: ");
      // dump() throws on invalid UTF-8; a result file must always serialize.
      report.dump(2);
      append(defects,
             csv_defects(Output::analytic_csv(closed_forms)),
             "analytic.csv: ");
      append(defects,
             table_defects(Output::analytic_table(closed_forms)),
             "table: ");
      return report;
    }
  } // namespace

  PipelineResult
  run_scene_pipeline(const std::string              &text,
                     const std::string              &extension,
                     const std::vector<std::string> &overrides,
                     const std::filesystem::path    &work_directory)
  {
    PipelineResult                 result;
    Parameters::ScenarioParameters scene;
    try
      {
        scene = Parameters::read_scenario(
          write_file(work_directory / ("scene" + extension), text).string(),
          overrides);
      }
    catch (const InputError &error)
      {
        result.error_message = error.what();
        if (result.error_message.empty())
          result.defects.push_back("InputError with an empty message");
        return result;
      }
    result.accepted             = true;
    const nlohmann::json report = checked_report(scene, result.defects);

    // results/<scene>/parameters.prm must reproduce the run it documents.
    const auto echoed =
      write_file(work_directory / "expanded.prm", scene.expanded_text);
    try
      {
        const auto again = Parameters::read_scenario(echoed.string(), {});
        std::vector<std::string> ignored;
        if (checked_report(again, ignored) != report)
          result.defects.push_back(
            "expanded parameters read back give a different analytic.json");
      }
    catch (const InputError &error)
      {
        result.defects.push_back(
          std::string("expanded parameters do not read back: ") + error.what());
      }
    return result;
  }
} // namespace FloorBlock::Fuzz
