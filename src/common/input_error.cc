#include <common/input_error.h>

namespace FloorBlock
{
  InputError::InputError(const std::string &message)
    : std::runtime_error(message)
  {}

  InputError::InputError(const std::string &parameter,
                         const std::string &value,
                         const std::string &allowed)
    : std::runtime_error("parameter '" + parameter + "' = '" + value +
                         "': " + allowed)
  {}
} // namespace FloorBlock
