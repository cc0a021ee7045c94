#pragma once

// The block-assembly mesher lives in the verification library, where the
// verification cases share it; tests keep their Testing:: names.
#include <verification/block_assembly_mesh.h>

namespace FloorBlock::Testing
{
  using Verification::BlockSpec;
  using Verification::make_block_assembly;
} // namespace FloorBlock::Testing
