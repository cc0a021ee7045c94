#pragma once

#include <cstdint>
#include <string>

namespace FloorBlock::Fuzz
{
  /**
   * @brief Seed and input count of a randomized test run. The ctest run uses
   * the fixed defaults; .ci/fuzz.sh varies them through the environment
   * variables FLOORBLOCK_FUZZ_SEED and FLOORBLOCK_FUZZ_INPUTS.
   */
  struct FuzzSettings
  {
    std::uint64_t seed;
    std::uint64_t n_inputs;
  };

  /** @brief Settings from the environment, else the given defaults. */
  FuzzSettings
  fuzz_settings(const std::uint64_t default_seed,
                const std::uint64_t default_n_inputs);
} // namespace FloorBlock::Fuzz
