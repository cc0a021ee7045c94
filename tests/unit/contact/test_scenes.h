#pragma once

// The helpers live in the contact library, where the verification cases
// share them; tests keep their Testing:: names.
#include <contact/verification_setup.h>

namespace FloorBlock
{
  namespace Testing
  {
    using Contact::fixed_support;
    using Contact::table_rock;

    inline Contact::ContactSolverSettings
    test_settings(const unsigned int degree = 1)
    {
      return Contact::verification_settings(degree);
    }
  } // namespace Testing
} // namespace FloorBlock
