#pragma once

#include <string>

namespace FloorBlock::Parameters
{
  /** @brief A stress or modulus for an error message: six significant
   * digits and its unit, "4e+07 Pa". */
  std::string
  pascals(double value);
} // namespace FloorBlock::Parameters
