#include <common/atomic_file.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace FloorBlock
{
  std::string
  temporary_name_for(const std::string &path)
  {
    const std::filesystem::path target(path);
    // Same folder, so the final rename never crosses a file system.
    return (target.parent_path() / ("." + target.filename().string() + ".tmp." +
                                    std::to_string(::getpid())))
      .string();
  }

  void
  commit_temporary_file(const std::string &temporary_path,
                        const std::string &final_path)
  {
    std::error_code error;
    std::filesystem::rename(temporary_path, final_path, error);
    if (error)
      {
        std::filesystem::remove(temporary_path, error);
        throw std::runtime_error("cannot move " + temporary_path + " to " +
                                 final_path);
      }
  }

  void
  write_file_atomically(const std::string &path, const std::string &contents)
  {
    const std::filesystem::path target(path);
    if (target.has_parent_path())
      std::filesystem::create_directories(target.parent_path());

    const std::string temporary = temporary_name_for(path);
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      out << contents;
      out.flush();
      if (!out)
        {
          std::filesystem::remove(temporary);
          throw std::runtime_error("cannot write " + temporary);
        }
    }
    commit_temporary_file(temporary, path);
  }
} // namespace FloorBlock
