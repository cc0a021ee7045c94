#include <parameters/value_text.h>

#include <sstream>

namespace FloorBlock::Parameters
{
  std::string
  pascals(const double value)
  {
    std::ostringstream text;
    text.precision(6);
    text << value << " Pa";
    return text.str();
  }
} // namespace FloorBlock::Parameters
