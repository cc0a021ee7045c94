// The Open MPI environment of a process that starts MPI by itself: its
// private environment directory and start-up settings (see
// common/singleton_mpi_environment.h).

#include <common/singleton_mpi_environment.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

using FloorBlock::SingletonMpiEnvironment;

namespace
{
  constexpr const char *tmpdir_variable = "OMPI_MCA_orte_tmpdir_base";

  /** Clears the variables the class reads, and restores them afterwards. */
  class SingletonMpiEnvironmentTest : public ::testing::Test
  {
  protected:
    void
    SetUp() override
    {
      std::vector<const char *> names = {tmpdir_variable,
                                         "OMPI_COMM_WORLD_SIZE",
                                         "PMIX_RANK"};
      for (const FloorBlock::MpiSetting &setting :
           FloorBlock::singleton_start_up_settings)
        names.push_back(setting.variable);
      for (const char *name : names)
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

  // The tool shall give a process that starts MPI by itself a temporary
  // directory of its own for Open MPI's environment directory, and remove it
  // when done.
  TEST_F(SingletonMpiEnvironmentTest,
         SingletonGetsAPrivateDirectoryRemovedAtTheEnd)
  {
    std::string path;
    {
      const SingletonMpiEnvironment environment;
      path = environment.path();
      ASSERT_FALSE(path.empty());
      EXPECT_TRUE(std::filesystem::is_directory(path));
      ASSERT_NE(std::getenv(tmpdir_variable), nullptr);
      EXPECT_EQ(std::string(std::getenv(tmpdir_variable)), path);
      // Two processes never share it.
      const SingletonMpiEnvironment other;
      EXPECT_TRUE(other.path().empty())
        << "the variable is set now: left alone";
    }
    EXPECT_FALSE(std::filesystem::exists(path));
  }

  // The tool shall leave a process started by mpirun, and a directory the
  // user chose, alone.
  TEST_F(SingletonMpiEnvironmentTest, LauncherAndUserSettingAreLeftAlone)
  {
    ::setenv("OMPI_COMM_WORLD_SIZE", "2", 1);
    {
      const SingletonMpiEnvironment environment;
      EXPECT_TRUE(environment.path().empty());
      EXPECT_EQ(std::getenv(tmpdir_variable), nullptr);
    }
    ::unsetenv("OMPI_COMM_WORLD_SIZE");
    ::setenv(tmpdir_variable, "/somewhere/of/the/user", 1);
    {
      const SingletonMpiEnvironment environment;
      EXPECT_TRUE(environment.path().empty());
      EXPECT_EQ(std::string(std::getenv(tmpdir_variable)),
                "/somewhere/of/the/user");
    }
  }

  // The tool shall start a singleton with the quick settings (ob1 messaging,
  // no helper daemon), keep a value the user set, and leave a process started
  // by mpirun alone.
  TEST_F(SingletonMpiEnvironmentTest,
         SingletonGetsTheStartUpSettingsUnlessSetOrLaunched)
  {
    {
      const SingletonMpiEnvironment environment;
      ASSERT_NE(std::getenv("OMPI_MCA_pml"), nullptr);
      EXPECT_EQ(std::string(std::getenv("OMPI_MCA_pml")), "ob1");
      ASSERT_NE(std::getenv("OMPI_MCA_ess_singleton_isolated"), nullptr);
      EXPECT_EQ(std::string(std::getenv("OMPI_MCA_ess_singleton_isolated")),
                "1");
    }
    ::unsetenv("OMPI_MCA_pml");
    ::unsetenv("OMPI_MCA_ess_singleton_isolated");

    ::setenv("OMPI_MCA_pml", "cm", 1);
    {
      const SingletonMpiEnvironment environment;
      EXPECT_EQ(std::string(std::getenv("OMPI_MCA_pml")), "cm");
    }
    ::unsetenv("OMPI_MCA_pml");
    ::unsetenv("OMPI_MCA_ess_singleton_isolated");

    ::setenv("PMIX_RANK", "0", 1);
    {
      const SingletonMpiEnvironment environment;
      EXPECT_EQ(std::getenv("OMPI_MCA_pml"), nullptr);
      EXPECT_EQ(std::getenv("OMPI_MCA_ess_singleton_isolated"), nullptr);
    }
  }
} // namespace
