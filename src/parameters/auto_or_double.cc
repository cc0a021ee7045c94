#include <parameters/auto_or_double.h>

#include <deal.II/base/utilities.h>

namespace FloorBlock::Parameters
{
  AutoOrDouble::AutoOrDouble(const double lower_bound, const double upper_bound)
    : number(lower_bound, upper_bound)
  {}

  bool
  AutoOrDouble::match(const std::string &test_string) const
  {
    return is_auto(test_string) || number.match(test_string);
  }

  std::string
  AutoOrDouble::description(const OutputStyle style) const
  {
    if (style == Machine)
      return "[AutoOr" + number.description(style).substr(1);
    return "auto or " + number.description(style);
  }

  std::unique_ptr<dealii::Patterns::PatternBase>
  AutoOrDouble::clone() const
  {
    return std::make_unique<AutoOrDouble>(*this);
  }

  bool
  is_auto(const std::string &value)
  {
    return dealii::Utilities::trim(value) == "auto";
  }
} // namespace FloorBlock::Parameters
