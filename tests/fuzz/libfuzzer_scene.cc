// libFuzzer entry point: coverage-guided version of SceneFuzz, built only
// with -DFLOORBLOCK_LIBFUZZER=ON and clang (see .ci/fuzz.sh).
//
// Input layout: the first byte picks the format ('j' = .json, 'x' = .xml,
// anything else = .prm); the rest is the scene text. Lines after a line
// "--set" are command-line overrides, one per line.

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <iostream>

#include "scene_pipeline.h"

namespace
{
  const std::string override_marker = "\n--set\n";

  const std::filesystem::path &
  work_directory()
  {
    static const std::filesystem::path path = [] {
      const auto folder =
        std::filesystem::temp_directory_path() /
        ("floorblock_libfuzzer_" + std::to_string(::getpid()));
      std::filesystem::create_directories(folder);
      return folder;
    }();
    return path;
  }

  std::string
  extension_for(const char selector)
  {
    return selector == 'j' ? ".json" : selector == 'x' ? ".xml" : ".prm";
  }
} // namespace

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  if (size == 0)
    return 0;
  const std::string        input(reinterpret_cast<const char *>(data), size);
  std::string              text = input.substr(1);
  std::vector<std::string> overrides;
  const auto               marker = text.find(override_marker);
  if (marker != std::string::npos)
    {
      std::string rest = text.substr(marker + override_marker.size());
      text.resize(marker + 1);
      for (std::size_t start = 0; start <= rest.size();)
        {
          const auto end = std::min(rest.find('\n', start), rest.size());
          overrides.push_back(rest.substr(start, end - start));
          start = end + 1;
        }
    }

  // Anything but InputError escapes and terminates: libFuzzer records a crash.
  const FloorBlock::Fuzz::PipelineResult result =
    FloorBlock::Fuzz::run_scene_pipeline(text,
                                         extension_for(input[0]),
                                         overrides,
                                         work_directory());
  if (!result.defects.empty())
    {
      for (const std::string &defect : result.defects)
        std::cerr << "defect: " << defect << '\n';
      std::abort();
    }
  return 0;
}
