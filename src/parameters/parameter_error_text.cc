#include <parameters/parameter_error_text.h>

#include <sstream>

namespace FloorBlock::Parameters
{
  namespace
  {
    std::string
    fold_whitespace(const std::string &text)
    {
      std::istringstream words(text);
      std::string        word, folded;
      while (words >> word)
        folded += (folded.empty() ? "" : " ") + word;
      return folded;
    }
  } // namespace

  std::string
  parameter_error_text(const dealii::ExceptionBase &error,
                       const std::string           &parameter_path,
                       const std::string           &value)
  {
    std::ostringstream info;
    error.print_info(info);
    std::string text = fold_whitespace(info.str());
    if (text.empty())
      text = error.get_exc_name();
    if (parameter_path.empty())
      return text;
    return "parameter '" + parameter_path + "' = '" + value + "': " + text;
  }
} // namespace FloorBlock::Parameters
