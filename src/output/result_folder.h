#pragma once

#include <parameters/scenario_parameters.h>

#include <nlohmann/json.hpp>

#include <string>

namespace FloorBlock::Output
{
  /**
   * @brief The folder a command writes into (results/<scene>/ by default).
   *
   * Every file goes in whole (temporary name, then rename), so an interrupted
   * run never leaves a truncated file. A run marks itself finished by writing
   * summary.json last (write_summary()); a folder without it is incomplete.
   * The folder is created on the first write, i.e. only after the inputs
   * were validated: bad input leaves no trace.
   */
  class ResultFolder
  {
  public:
    /**
     * @param[in] path The folder.
     * @param[in] writes False on the processes of a distributed solve
     *   other than the first: they compute the same files, which the first
     *   process writes; every write is then skipped.
     */
    explicit ResultFolder(const std::string &path, const bool writes = true);

    /** @brief Whether this process writes the files (see the constructor). */
    bool
    writes_files() const;

    /** @brief Writes @p contents to <folder>/<file_name> atomically. */
    void
    write(const std::string &file_name, const std::string &contents) const;

    /** @brief Writes pretty-printed JSON. */
    void
    write_json(const std::string &file_name, const nlohmann::json &value) const;

    /** @brief Echoes the scene: original.prm (as read), parameters.prm (expanded). */
    void
    write_inputs(const Parameters::ScenarioParameters &scene) const;

    /**
     * @brief Removes a summary.json left by an earlier run, so the folder
     * reads as unfinished until this run writes its own.
     */
    void
    mark_unfinished() const;

    /** @brief Writes summary.json: call last. */
    void
    write_summary(const nlohmann::json &summary) const;

    /** @brief <folder>/<file_name>. */
    std::string
    path_of(const std::string &file_name) const;

  private:
    const std::string folder;
    const bool        writes;
  };
} // namespace FloorBlock::Output
