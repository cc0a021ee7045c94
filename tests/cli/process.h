#pragma once

#include <string>

namespace FloorBlockTest
{
  /** What a finished floorblock process left behind. */
  struct ProcessResult
  {
    int         exit_code;
    std::string output; ///< stdout and stderr together
  };

  /**
   * @brief Runs build/floorblock with @p arguments (already shell-quoted)
   * from the source folder, so relative scene paths resolve as in the README.
   */
  ProcessResult
  run_floorblock(const std::string &arguments);

  /** @brief A fresh, not yet existing folder under the system temp folder. */
  std::string
  fresh_output_folder(const std::string &name);

  /** @brief Quotes @p text for the shell. */
  std::string
  shell_quoted(const std::string &text);
} // namespace FloorBlockTest
