// The private Open MPI session directory of a process that starts MPI by
// itself (see common/mpi_session_directory.h).

#include <common/mpi_session_directory.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

using FloorBlock::PrivateMpiSessionDirectory;

namespace
{
  constexpr const char *tmpdir_variable = "OMPI_MCA_orte_tmpdir_base";

  /** Clears the variables the class reads, and restores them afterwards. */
  class MpiSessionDirectoryTest : public ::testing::Test
  {
  protected:
    void
    SetUp() override
    {
      for (const char *name :
           {tmpdir_variable, "OMPI_COMM_WORLD_SIZE", "PMIX_RANK"})
        {
          const char *value = std::getenv(name);
          saved.emplace_back(name, value ? value : "", value != nullptr);
          ::unsetenv(name);
        }
    }
    void
    TearDown() override
    {
      for (const auto &[name, value, was_set] : saved)
        if (was_set)
          ::setenv(name.c_str(), value.c_str(), 1);
        else
          ::unsetenv(name.c_str());
    }
    std::vector<std::tuple<std::string, std::string, bool>> saved;
  };
} // namespace

// The tool shall give a process that starts MPI by itself a session
// directory of its own, and remove it when done.
TEST_F(MpiSessionDirectoryTest, SingletonGetsAPrivateDirectoryRemovedAtTheEnd)
{
  std::string path;
  {
    const PrivateMpiSessionDirectory session;
    path = session.path();
    ASSERT_FALSE(path.empty());
    EXPECT_TRUE(std::filesystem::is_directory(path));
    ASSERT_NE(std::getenv(tmpdir_variable), nullptr);
    EXPECT_EQ(std::string(std::getenv(tmpdir_variable)), path);
    // Two processes never share it.
    const PrivateMpiSessionDirectory other;
    EXPECT_TRUE(other.path().empty()) << "the variable is set now: left alone";
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

// The tool shall leave a process started by mpirun, and a directory the
// user chose, alone.
TEST_F(MpiSessionDirectoryTest, LauncherAndUserSettingAreLeftAlone)
{
  ::setenv("OMPI_COMM_WORLD_SIZE", "2", 1);
  {
    const PrivateMpiSessionDirectory session;
    EXPECT_TRUE(session.path().empty());
    EXPECT_EQ(std::getenv(tmpdir_variable), nullptr);
  }
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  ::setenv(tmpdir_variable, "/somewhere/of/the/user", 1);
  {
    const PrivateMpiSessionDirectory session;
    EXPECT_TRUE(session.path().empty());
    EXPECT_EQ(std::string(std::getenv(tmpdir_variable)),
              "/somewhere/of/the/user");
  }
}
