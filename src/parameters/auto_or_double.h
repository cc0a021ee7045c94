#pragma once

#include <deal.II/base/patterns.h>

#include <memory>
#include <string>

namespace FloorBlock::Parameters
{
  /**
   * @brief Pattern of an entry that is either the word "auto" (the program
   * derives the value from other entries) or a number in [lower, upper].
   *
   * deal.II's ParameterHandler cannot tell a value the user set from its
   * default, so an entry whose value can follow from others declares "auto"
   * as its default and this pattern keeps the numeric range bounded.
   */
  class AutoOrDouble : public dealii::Patterns::PatternBase
  {
  public:
    AutoOrDouble(const double lower_bound, const double upper_bound);

    bool
    match(const std::string &test_string) const override;

    std::string
    description(const OutputStyle style = Machine) const override;

    std::unique_ptr<dealii::Patterns::PatternBase>
    clone() const override;

  private:
    const dealii::Patterns::Double number;
  };

  /** @brief Whether an AutoOrDouble entry's value is the word "auto". */
  bool
  is_auto(const std::string &value);
} // namespace FloorBlock::Parameters
