#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <vector>

namespace FloorBlock::Parameters
{
  /**
   * @brief One line for the user from a ParameterHandler exception.
   *
   * deal.II's own what() is a multi-line block with source locations meant
   * for developers; its print_info() part already names the line, file,
   * entry, value and pattern. This keeps that part and folds it onto one
   * line, prefixed by the parameter path and value when the caller knows
   * them (overrides from the command line have no file line).
   */
  std::string
  parameter_error_text(const dealii::ExceptionBase &error,
                       const std::string           &parameter_path,
                       const std::string           &value);

  /**
   * @brief Every entry declared in @p prm as "Subsection/Entry" (nested:
   * "A/B/Entry").
   */
  std::vector<std::string>
  entry_paths(const dealii::ParameterHandler &prm);

  /**
   * @brief Every entry of @p prm by path, with the unit its documentation
   * names ("... Units: Pa." gives "Pa"; "" where it names none).
   */
  std::map<std::string, std::string>
  entry_units(const dealii::ParameterHandler &prm);

  /**
   * @brief Up to three declared "Subsection/Entry" paths whose entry name
   * is nearest to @p name: at most max(2, length/3) letters apart
   * (Levenshtein, ignoring case), or containing it or contained in it.
   */
  std::vector<std::string>
  nearest_names(const std::string              &name,
                const std::vector<std::string> &declared_paths);

  /**
   * @brief What to do about a ParameterHandler message @p message, or "":
   * for an unknown entry the nearest declared names ("did you mean ...?");
   * for a subsection entered inside another, or a file that ends inside
   * one, the subsection still open, where it was opened and where its
   * `end` belongs (from @p file_text, the scene file as read).
   */
  std::string
  parse_error_hint(const std::string              &message,
                   const std::string              &file_text,
                   const std::vector<std::string> &declared_paths);
} // namespace FloorBlock::Parameters
