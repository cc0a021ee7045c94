#include <common/blas_threads.h>

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace
{
  const char *const count_variables[] = {"OPENBLAS_NUM_THREADS",
                                         "GOTO_NUM_THREADS",
                                         "OMP_NUM_THREADS"};

  /** Clears the thread-count variables for one test, restoring them after. */
  class WithoutThreadVariables : public ::testing::Test
  {
  protected:
    void
    SetUp() override
    {
      for (int k = 0; k < 3; ++k)
        {
          if (const char *value = std::getenv(count_variables[k]))
            saved[k] = value;
          unsetenv(count_variables[k]);
        }
      // These tests load no deal.II: load the system BLAS as floorblock
      // does (through deal.II's LAPACK), with its symbols visible to dlsym.
      ASSERT_NE(dlopen("libblas.so.3", RTLD_NOW | RTLD_GLOBAL), nullptr)
        << dlerror();
      set_threads = reinterpret_cast<void (*)(int)>(
        dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    }

    void
    TearDown() override
    {
      for (int k = 0; k < 3; ++k)
        if (saved[k])
          setenv(count_variables[k], saved[k]->c_str(), 1);
        else
          unsetenv(count_variables[k]);
    }

    std::optional<std::string> saved[3];
    void (*set_threads)(int) = nullptr;
  };

  // .ci/setup.sh installs OpenBLAS as Debian's libblas.so.3.
  TEST_F(WithoutThreadVariables, SetsOneThread)
  {
    ASSERT_NE(set_threads, nullptr) << "libblas.so.3 is not OpenBLAS";
    set_threads(2);
    ASSERT_EQ(FloorBlock::blas_thread_count(), 2);
    EXPECT_TRUE(FloorBlock::limit_blas_to_one_thread());
    EXPECT_EQ(FloorBlock::blas_thread_count(), 1);
  }

  TEST_F(WithoutThreadVariables, LeavesTheCountTheUserChose)
  {
    ASSERT_NE(set_threads, nullptr) << "libblas.so.3 is not OpenBLAS";
    for (const char *variable : count_variables)
      {
        set_threads(2);
        setenv(variable, "2", 1);
        EXPECT_FALSE(FloorBlock::limit_blas_to_one_thread()) << variable;
        EXPECT_EQ(FloorBlock::blas_thread_count(), 2) << variable;
        unsetenv(variable);
      }
  }
} // namespace
