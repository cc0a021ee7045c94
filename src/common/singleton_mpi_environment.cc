#include <common/singleton_mpi_environment.h>

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

    /**
     * A private directory for Open MPI's session directory, or "" if none
     * could be made.
     */
    std::string
    make_private_temporary_directory()
    {
      std::error_code   ignored;
      const std::string pattern =
        (std::filesystem::temp_directory_path(ignored) /
         "floorblock-mpi-XXXXXX")
          .string();
      std::vector<char> name(pattern.begin(), pattern.end());
      name.push_back('\0');
      if (::mkdtemp(name.data()) == nullptr)
        return "";
      return name.data();
    }
  } // namespace

  SingletonMpiEnvironment::SingletonMpiEnvironment()
  {
    if (started_by_a_launcher())
      return;
    // overwrite = 0 throughout: what the user set wins.
    for (const MpiSetting &setting : singleton_start_up_settings)
      ::setenv(setting.variable, setting.value, /*overwrite=*/0);

    constexpr const char *tmpdir_variable = "OMPI_MCA_orte_tmpdir_base";
    if (std::getenv(tmpdir_variable) != nullptr)
      return;
    directory = make_private_temporary_directory();
    if (!directory.empty())
      ::setenv(tmpdir_variable, directory.c_str(), /*overwrite=*/0);
  }

  SingletonMpiEnvironment::~SingletonMpiEnvironment()
  {
    if (directory.empty())
      return;
    std::error_code ignored;
    std::filesystem::remove_all(directory, ignored);
  }

  const std::string &
  SingletonMpiEnvironment::path() const
  {
    return directory;
  }
} // namespace FloorBlock
