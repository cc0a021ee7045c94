#pragma once

#include <string>

namespace FloorBlock::Parameters
{
  /** @brief The shortest text that reads back as @p value ("89", "4e+07",
   * "0.1"): for messages, and for setting a parameter to that exact value. */
  std::string
  number(double value);

  /** @brief A stress or modulus for an error message: six significant
   * digits and its unit, "4e+07 Pa". */
  std::string
  pascals(double value);

  /**
   * @brief A count chosen from a Selection pattern ("2|3", "auto|0|1|...")
   * as a number. Throws InputError naming @p parameter and @p allowed if @p
   * value is not a plain decimal number: a Selection can pass text it was not
   * declared with (a value with control bytes in a fuzzed file did).
   */
  unsigned int
  selected_count(const std::string &value,
                 const std::string &parameter,
                 const std::string &allowed);
} // namespace FloorBlock::Parameters
