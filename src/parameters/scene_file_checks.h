#pragma once

#include <string>

namespace FloorBlock::Parameters
{
  /**
   * @brief Refuses what deal.II's ParameterHandler would read unsafely:
   * checks on the raw text of a scene file, made before
   * ParameterHandler::parse_input sees it.
   *
   * The file type is chosen as deal.II chooses it: the text after the last
   * '.' of the path, in any case.
   * - `prm`: "include <file>" statements. deal.II opens any path: the scene
   *   itself (unbounded recursion, a stack-overflow crash), /dev/zero (one
   *   endless line, a hang), a directory (silently nothing). Scenes are
   *   self-contained, so the statement is refused.
   * - `json`, `xml`: node names that deal.II's reader cannot take. deal.II
   *   walks the Boost property tree level by level, treats a node with a
   *   "value" or "alias" child as an entry (and reads nothing below it), any
   *   other node as a subsection, and passes every name it meets through
   *   its `demangle`, which requires each '_' to be followed by two
   *   lowercase hex digits (deal.II's own escape, "Number_20of_20blocks").
   *   Refused at those levels: a name without characters (a JSON array or a
   *   member named "": a subsection with an empty path violates a
   *   precondition of Boost's `basic_ptree::force_path`), and a name with
   *   an '_' that is not such an escape (deal.II's debug library aborts, its
   *   release library reads past the name's end). Both are an assertion in
   *   debug builds and undefined behaviour in release builds.
   *
   *   Refused before any parsing: nesting deeper than 100 levels (Boost's
   *   recursive parsers overflow the stack on very deep text; a scene needs
   *   a few levels).
   *
   * Text that does not parse as JSON or XML passes: deal.II's own reader
   * reports the syntax error.
   *
   * @param[in] path The scene file's path, for the message and its type.
   * @param[in] text The whole file.
   * @throws InputError naming the file, the offending statement or node and
   *   what is allowed.
   */
  void
  check_scene_file_text(const std::string &path, const std::string &text);
} // namespace FloorBlock::Parameters
