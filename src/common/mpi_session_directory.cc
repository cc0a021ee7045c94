#include <common/mpi_session_directory.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace FloorBlock
{
  namespace
  {
    /** Set by mpirun/orted (Open MPI) or PMIx in every process they start. */
    bool
    started_by_a_launcher()
    {
      return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr ||
             std::getenv("PMIX_RANK") != nullptr;
    }
  } // namespace

  PrivateMpiSessionDirectory::PrivateMpiSessionDirectory()
  {
    constexpr const char *variable = "OMPI_MCA_orte_tmpdir_base";
    if (started_by_a_launcher() || std::getenv(variable) != nullptr)
      return;
    std::error_code   ignored;
    const std::string pattern =
      (std::filesystem::temp_directory_path(ignored) / "floorblock-mpi-XXXXXX")
        .string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (::mkdtemp(name.data()) == nullptr)
      return;
    directory = name.data();
    ::setenv(variable, directory.c_str(), /*overwrite=*/0);
  }

  PrivateMpiSessionDirectory::~PrivateMpiSessionDirectory()
  {
    if (directory.empty())
      return;
    std::error_code ignored;
    std::filesystem::remove_all(directory, ignored);
  }

  const std::string &
  PrivateMpiSessionDirectory::path() const
  {
    return directory;
  }
} // namespace FloorBlock
