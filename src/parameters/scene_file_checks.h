#pragma once

#include <string>

namespace FloorBlock::Parameters
{
  /**
   * @brief Refuses what deal.II's ParameterHandler would read unsafely:
   * checks on the raw text of a scene file, made before
   * ParameterHandler::parse_input sees it.
   *
   * - `.prm`: "include <file>" statements. deal.II opens any path: the scene
   *   itself (unbounded recursion, a stack-overflow crash), /dev/zero (one
   *   endless line, a hang), a directory (silently nothing). Scenes are
   *   self-contained, so the statement is refused.
   * - `.json`, `.xml`: nodes without a name. A JSON array, or an object
   *   member named "", becomes a Boost property-tree node with an empty key;
   *   deal.II then enters a subsection with an empty path, which violates a
   *   precondition of `basic_ptree::force_path` (an assertion in debug
   *   builds, undefined behaviour in release builds).
   *
   * Text that does not parse as JSON or XML passes: deal.II's own reader
   * reports the syntax error.
   *
   * @param[in] path The scene file's path, for the message and its extension.
   * @param[in] text The whole file.
   * @throws InputError naming the file, the offending statement or node and
   *   what is allowed.
   */
  void
  check_scene_file_text(const std::string &path, const std::string &text);
} // namespace FloorBlock::Parameters
