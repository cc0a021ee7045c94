#pragma once

#include <string>

namespace FloorBlock::Compare
{
  /**
   * @brief A joint as the contact solver names it: "vertical j" (between
   * block j and block j+1, or the face block for j = n) or "bedding i"
   * (under block i), in the chapter's numbering.
   */
  struct JointName
  {
    std::string  kind;       ///< "vertical" or "bedding"
    unsigned int number = 0; ///< j or i; 0 if the name has no number
  };

  /**
   * @brief The face joint's name, "vertical n": between block n, next to
   * the face, and the face block.
   */
  std::string
  face_joint_name(unsigned int n_blocks);

  /** @brief Splits "vertical 3" into its kind and number. */
  JointName
  parse_joint_name(const std::string &name);
} // namespace FloorBlock::Compare
