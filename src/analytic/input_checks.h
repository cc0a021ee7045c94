#pragma once

#include <cmath>

namespace FloorBlock::Analytic
{
  namespace Internal
  {
    /** @brief True if @p value is finite and > 0 (a valid length, load,
     *  modulus). */
    inline bool
    is_positive(const double value)
    {
      return std::isfinite(value) && value > 0.;
    }
  } // namespace Internal
} // namespace FloorBlock::Analytic
