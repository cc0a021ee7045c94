#include "fuzz_settings.h"

#include <cstdlib>
#include <stdexcept>

namespace FloorBlock::Fuzz
{
  namespace
  {
    std::uint64_t
    from_environment(const char *variable, const std::uint64_t fallback)
    {
      const char *text = std::getenv(variable);
      if (text == nullptr || *text == '\0')
        return fallback;
      char                    *end   = nullptr;
      const unsigned long long value = std::strtoull(text, &end, 10);
      if (*end != '\0')
        throw std::invalid_argument(std::string(variable) +
                                    " must be a non-negative integer");
      return value;
    }
  } // namespace

  FuzzSettings
  fuzz_settings(const std::uint64_t default_seed,
                const std::uint64_t default_n_inputs)
  {
    return {from_environment("FLOORBLOCK_FUZZ_SEED", default_seed),
            from_environment("FLOORBLOCK_FUZZ_INPUTS", default_n_inputs)};
  }
} // namespace FloorBlock::Fuzz
