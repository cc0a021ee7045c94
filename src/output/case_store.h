#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace FloorBlock::Output
{
  /**
   * @brief One JSON file per finished case of a sweep, so a sweep can be
   * interrupted and resumed: a case whose file exists is done and is not
   * computed again. Files are written whole (temporary name, then rename),
   * so an interrupted case leaves nothing behind.
   */
  class CaseStore
  {
  public:
    /** @param[in] folder Where the case files live (created on first store). */
    explicit CaseStore(const std::string &folder);

    /** @brief Whether @p case_id has a finished file. */
    bool
    has(const std::string &case_id) const;

    /** @brief Writes the finished case atomically. */
    void
    store(const std::string &case_id, const nlohmann::json &result) const;

    /** @brief Reads a finished case; throws std::runtime_error if unreadable. */
    nlohmann::json
    load(const std::string &case_id) const;

    /** @brief <folder>/<case_id>.json */
    std::string
    path_of(const std::string &case_id) const;

  private:
    const std::string folder;
  };
} // namespace FloorBlock::Output
