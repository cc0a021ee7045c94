#include <compare/joint_name.h>

#include <sstream>

namespace FloorBlock::Compare
{
  std::string
  face_joint_name(const unsigned int n_blocks)
  {
    return "vertical " + std::to_string(n_blocks);
  }

  JointName
  parse_joint_name(const std::string &name)
  {
    JointName          parsed;
    std::istringstream words(name);
    words >> parsed.kind >> parsed.number;
    return parsed;
  }
} // namespace FloorBlock::Compare
