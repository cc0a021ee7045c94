#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace FloorBlock::Fuzz
{
  /** What the product did with one input. */
  struct PipelineResult
  {
    bool        accepted = false; ///< false: read_scenario threw InputError
    std::string error_message;    ///< the InputError text when rejected
    /// Broken promises: non-finite output, unknown status, empty error
    /// message, expanded parameters that do not read back. Empty = clean.
    std::vector<std::string> defects;
  };

  /**
   * @brief Runs one scene through everything the `analytic` command does
   * short of writing results: Parameters::read_scenario,
   * Scene::evaluate_closed_forms and the JSON, CSV and table writers; then
   * re-reads the expanded parameters (parameters.prm) and requires the same
   * analytic.json.
   *
   * @param[in] text Scene file content.
   * @param[in] extension ".prm", ".json" or ".xml": how deal.II parses it.
   * @param[in] overrides "Subsection/Entry=value" strings as from --set.
   * @param[in] work_directory Existing folder for the scene file.
   * @return Accepted/rejected and the defects found.
   * @throws Anything other than InputError that the product throws: for bad
   * input that is itself a defect, and the caller reports it.
   */
  PipelineResult
  run_scene_pipeline(const std::string              &text,
                     const std::string              &extension,
                     const std::vector<std::string> &overrides,
                     const std::filesystem::path    &work_directory);
} // namespace FloorBlock::Fuzz
