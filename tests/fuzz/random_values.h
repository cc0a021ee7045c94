#pragma once

#include <cstddef>
#include <random>
#include <string>

namespace FloorBlock::Fuzz
{
  /** The one random engine of the fuzz tests: seeded, so every run repeats. */
  using RandomEngine = std::mt19937_64;

  /** @brief A uniformly drawn index in [0, count). @pre count > 0. */
  std::size_t
  random_index(RandomEngine &engine, const std::size_t count);

  /** @brief True with the given probability (0..1). */
  bool
  random_chance(RandomEngine &engine, const double probability);

  /**
   * @brief A hostile parameter value: plausible and out-of-range numbers,
   * huge, tiny, denormal, negative, nan/inf spellings, non-numeric words,
   * empty and blank strings, unicode digits, very long strings, random bytes,
   * comma lists and selection-like words.
   */
  std::string
  random_value(RandomEngine &engine);

  /** @brief @p length random bytes (any value 1..255; no NUL). */
  std::string
  random_bytes(RandomEngine &engine, const std::size_t length);
} // namespace FloorBlock::Fuzz

namespace FloorBlock::Fuzz
{
  /**
   * @brief A hostile double: NaN, +-inf, +-0, denormal, +-huge, and values
   * of ordinary size for lengths, angles and forces.
   */
  double
  random_double(RandomEngine &engine);
} // namespace FloorBlock::Fuzz
