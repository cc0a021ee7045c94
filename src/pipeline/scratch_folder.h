#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace FloorBlock::Pipeline
{
  /**
   * @brief A folder of its own under the system's temporary directory for
   * one case's solve (its mesh and files), removed however the solve ends:
   * studies keep only the records they store.
   */
  struct ScratchFolder
  {
    /** @param[in] name Unique among this process's cases. */
    explicit ScratchFolder(const std::string &name)
      : path(std::filesystem::temp_directory_path() /
             ("floorblock_case_" + std::to_string(::getpid()) + "_" + name))
    {}

    ~ScratchFolder()
    {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }

    ScratchFolder(const ScratchFolder &) = delete;
    ScratchFolder &
    operator=(const ScratchFolder &) = delete;

    const std::filesystem::path path;
  };
} // namespace FloorBlock::Pipeline
