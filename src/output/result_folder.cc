#include <common/atomic_file.h>
#include <output/result_folder.h>

#include <filesystem>

namespace FloorBlock::Output
{
  ResultFolder::ResultFolder(const std::string &path, const bool writes)
    : folder(path)
    , writes(writes)
  {}

  bool
  ResultFolder::writes_files() const
  {
    return writes;
  }

  std::string
  ResultFolder::path_of(const std::string &file_name) const
  {
    return (std::filesystem::path(folder) / file_name).string();
  }

  void
  ResultFolder::write(const std::string &file_name,
                      const std::string &contents) const
  {
    if (writes)
      write_file_atomically(path_of(file_name), contents);
  }

  void
  ResultFolder::write_json(const std::string    &file_name,
                           const nlohmann::json &value) const
  {
    // Two-space indent keeps the files readable and diffable.
    write(file_name, value.dump(2) + "\n");
  }

  void
  ResultFolder::write_inputs(const Parameters::ScenarioParameters &scene) const
  {
    write("original.prm", scene.original_text);
    write("parameters.prm", scene.expanded_text);
  }

  void
  ResultFolder::mark_unfinished() const
  {
    if (!writes)
      return;
    std::error_code ignored;
    std::filesystem::remove(path_of("summary.json"), ignored);
  }

  void
  ResultFolder::write_summary(const nlohmann::json &summary) const
  {
    write_json("summary.json", summary);
  }
} // namespace FloorBlock::Output
