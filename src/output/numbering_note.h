#pragma once

namespace FloorBlock::Output
{
  /// Stated in every output file's header: the chapter's block numbering.
  constexpr const char *numbering_note =
    "Block numbering follows the chapter: block 1 at the free end, block n "
    "next to the face block; Q_i acts between block i and block i+1, Q_n "
    "between block n and the face block.";
} // namespace FloorBlock::Output
