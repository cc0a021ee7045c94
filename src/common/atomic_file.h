#pragma once

#include <string>

namespace FloorBlock
{
  /**
   * @brief Writes @p contents to @p path so that a reader never sees a
   * partial file: the text goes to a temporary name in the same folder,
   * is flushed to disk, and is then renamed over @p path.
   *
   * Creates the parent folder if needed. Throws std::runtime_error on any
   * I/O failure, leaving no temporary file behind.
   */
  void
  write_file_atomically(const std::string &path, const std::string &contents);

  /**
   * @brief Renames an already complete temporary file into place, for writers
   * (VTU, PNG) that can only write to a path themselves.
   */
  void
  commit_temporary_file(const std::string &temporary_path,
                        const std::string &final_path);

  /** @brief The temporary name used for @p path: same folder, hidden, unique per process. */
  std::string
  temporary_name_for(const std::string &path);
} // namespace FloorBlock
