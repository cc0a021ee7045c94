#include <common/blas_threads.h>

#include <dlfcn.h>

#include <cstdlib>
#include <initializer_list>

namespace FloorBlock
{
  namespace
  {
    /** OpenBLAS's function @p name in this process, or nullptr. */
    void *
    openblas_function(const char *name)
    {
      return dlsym(RTLD_DEFAULT, name);
    }
  } // namespace

  bool
  limit_blas_to_one_thread()
  {
    for (const char *variable :
         {"OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS"})
      if (std::getenv(variable) != nullptr)
        return false;
    using SetThreads       = void (*)(int);
    const auto set_threads = reinterpret_cast<SetThreads>(
      openblas_function("openblas_set_num_threads"));
    if (set_threads == nullptr)
      return false;
    set_threads(1);
    return true;
  }

  int
  blas_thread_count()
  {
    using GetThreads       = int (*)();
    const auto get_threads = reinterpret_cast<GetThreads>(
      openblas_function("openblas_get_num_threads"));
    return get_threads != nullptr ? get_threads() : 0;
  }
} // namespace FloorBlock
