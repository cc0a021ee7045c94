#include "loaded_blas.h"

#include <dlfcn.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace FloorBlock::Benchmark
{
  LoadedBlas
  inspect_and_limit_blas()
  {
    LoadedBlas    blas;
    std::ifstream maps("/proc/self/maps");
    std::string   line;
    while (std::getline(maps, line))
      {
        const auto path_start = line.find('/');
        if (path_start == std::string::npos)
          continue;
        const std::string path    = line.substr(path_start);
        const std::string file    = path.substr(path.rfind('/') + 1);
        const bool        is_blas = file.find("blas") != std::string::npos ||
                             file.find("lapack") != std::string::npos;
        // libgslcblas (GSL) and libCombBLAS (graph algorithms) are not the
        // BLAS that Trilinos calls.
        const bool unrelated = file.find("gslcblas") != std::string::npos ||
                               file.find("CombBLAS") != std::string::npos;
        if (is_blas && !unrelated &&
            std::find(blas.libraries.begin(), blas.libraries.end(), path) ==
              blas.libraries.end())
          blas.libraries.push_back(path);
      }
    const bool openblas =
      std::any_of(blas.libraries.begin(),
                  blas.libraries.end(),
                  [](const std::string &path) {
                    return path.find("openblas") != std::string::npos;
                  });
    const bool reference =
      std::any_of(blas.libraries.begin(),
                  blas.libraries.end(),
                  [](const std::string &path) {
                    return path.find("/blas/libblas") != std::string::npos;
                  });
    blas.name = openblas  ? "OpenBLAS" :
                reference ? "reference BLAS" :
                            "unknown";

    using SetThreads = void (*)(int);
    if (const auto set_threads = reinterpret_cast<SetThreads>(
          dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      {
        set_threads(1);
        blas.limited_to_one_thread = true;
      }
    return blas;
  }
} // namespace FloorBlock::Benchmark
