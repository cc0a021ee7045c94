#include <common/input_error.h>
#include <parameters/value_text.h>

#include <algorithm>
#include <charconv>
#include <sstream>

namespace FloorBlock::Parameters
{
  std::string
  number(const double value)
  {
    char       text[32];
    const auto end = std::to_chars(text, text + sizeof(text), value).ptr;
    return std::string(text, end);
  }

  std::string
  pascals(const double value)
  {
    std::ostringstream text;
    text.precision(6);
    text << value << " Pa";
    return text.str();
  }

  unsigned int
  selected_count(const std::string &value,
                 const std::string &parameter,
                 const std::string &allowed)
  {
    const bool digits =
      !value.empty() && value.size() <= 3 &&
      std::all_of(value.begin(), value.end(), [](const char c) {
        return c >= '0' && c <= '9';
      });
    if (!digits)
      throw InputError(parameter, value, "must be " + allowed);
    return static_cast<unsigned int>(std::stoul(value));
  }
} // namespace FloorBlock::Parameters
