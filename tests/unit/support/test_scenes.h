#pragma once

// The helpers live in the verification library, where the verification
// cases share them; tests keep their Testing:: names.
#include <verification/verification_setup.h>

namespace FloorBlock::Testing
{
  using Verification::fixed_support;
  using Verification::table_rock;

  inline Contact::ContactSolverSettings
  test_settings(const unsigned int degree = 1)
  {
    return Verification::verification_settings(degree);
  }
} // namespace FloorBlock::Testing
