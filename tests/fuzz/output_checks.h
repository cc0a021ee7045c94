#pragma once

#include <scene/closed_forms.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

/**
 * Checks that the fuzz tests apply to every accepted scene. Each returns a
 * list of defects in words (empty = clean), so one input can report all its
 * problems at once.
 */
namespace FloorBlock::Fuzz
{
  /** @brief Whether @p name is Analytic::to_string of some Status value. */
  bool
  is_known_status(const std::string &name);

  /**
   * @brief analytic.json: no null (nlohmann writes NaN/inf as null), every
   * floating value finite, every "status"/"*_status" key a known status.
   */
  std::vector<std::string>
  json_defects(const nlohmann::json &report);

  /**
   * @brief analytic.csv: rectangular, "*_status" cells known statuses, every
   * other cell empty or a complete, finite number.
   */
  std::vector<std::string>
  csv_defects(const std::string &csv);

  /** @brief The console table: no "nan"/"inf" printed as a number. */
  std::vector<std::string>
  table_defects(const std::string &table);

  /** @brief The structs themselves: every double finite, statuses valid. */
  std::vector<std::string>
  closed_form_defects(const Scene::ClosedForms &closed_forms);
} // namespace FloorBlock::Fuzz
