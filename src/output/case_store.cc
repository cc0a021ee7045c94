#include <common/atomic_file.h>
#include <output/case_store.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace FloorBlock::Output
{
  CaseStore::CaseStore(const std::string &folder)
    : folder(folder)
  {}

  std::string
  CaseStore::path_of(const std::string &case_id) const
  {
    return (std::filesystem::path(folder) / (case_id + ".json")).string();
  }

  bool
  CaseStore::has(const std::string &case_id) const
  {
    return std::filesystem::is_regular_file(path_of(case_id));
  }

  void
  CaseStore::store(const std::string    &case_id,
                   const nlohmann::json &result) const
  {
    write_file_atomically(path_of(case_id), result.dump(2) + "\n");
  }

  nlohmann::json
  CaseStore::load(const std::string &case_id) const
  {
    std::ifstream in(path_of(case_id));
    if (!in)
      throw std::runtime_error("cannot read " + path_of(case_id));
    return nlohmann::json::parse(in);
  }
} // namespace FloorBlock::Output
