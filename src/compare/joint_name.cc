#include <compare/joint_name.h>

#include <sstream>

namespace FloorBlock::Compare
{
  JointName
  parse_joint_name(const std::string &name)
  {
    JointName          parsed;
    std::istringstream words(name);
    words >> parsed.kind >> parsed.number;
    return parsed;
  }
} // namespace FloorBlock::Compare
