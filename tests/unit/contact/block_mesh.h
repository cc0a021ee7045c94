#pragma once

// The block-assembly mesher lives in the contact library, where the
// verification cases share it; tests keep their Testing:: names.
#include <contact/block_assembly_mesh.h>

namespace FloorBlock
{
  namespace Testing
  {
    using Contact::BlockSpec;
    using Contact::make_block_assembly;
  } // namespace Testing
} // namespace FloorBlock
