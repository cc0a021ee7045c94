#pragma once

#include <deal.II/base/exceptions.h>

#include <string>

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
} // namespace FloorBlock::Parameters
