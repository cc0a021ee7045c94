#include <common/input_error.h>
#include <parameters/uncertain_inputs.h>
#include <parameters/value_text.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>

namespace FloorBlock::Parameters
{
  namespace
  {
    const std::string inputs_parameter       = "Uncertainty/Inputs";
    const std::string correlations_parameter = "Uncertainty/Correlations";

    std::string
    trimmed(const std::string &text)
    {
      const auto first = text.find_first_not_of(" \t\n\r");
      if (first == std::string::npos)
        return "";
      const auto last = text.find_last_not_of(" \t\n\r");
      return text.substr(first, last - first + 1);
    }

    /** Non-empty pieces of @p text between @p separator, trimmed. */
    std::vector<std::string>
    pieces(const std::string &text, const char separator)
    {
      std::vector<std::string> result;
      std::string::size_type   start = 0;
      while (start <= text.size())
        {
          const auto end = std::min(text.find(separator, start), text.size());
          const std::string piece = trimmed(text.substr(start, end - start));
          if (!piece.empty())
            result.push_back(piece);
          start = end + 1;
        }
      return result;
    }

    /** The whole of @p text as a finite number, or nothing. */
    bool
    read_number(const std::string &text, double &value)
    {
      const std::string number = trimmed(text);
      if (number.empty())
        return false;
      std::size_t used = 0;
      try
        {
          value = std::stod(number, &used);
        }
      catch (const std::exception &)
        {
          return false;
        }
      return used == number.size() && std::isfinite(value);
    }

    struct FamilySyntax
    {
      DistributionFamily family;
      std::string        arguments; ///< their names, for messages
      std::size_t        n_required;
      bool               may_truncate; ///< takes min, max after them
    };

    /** Family names as written (lower case, single spaces). */
    const std::vector<std::pair<std::string, FamilySyntax>> families = {
      {"normal", {DistributionFamily::normal, "mean, sd", 2, true}},
      {"truncated normal",
       {DistributionFamily::normal, "mean, sd, min, max", 4, false}},
      {"lognormal", {DistributionFamily::lognormal, "mean, sd", 2, true}},
      {"uniform", {DistributionFamily::uniform, "min, max", 2, false}},
      {"triangular",
       {DistributionFamily::triangular, "min, mode, max", 3, false}},
      {"beta", {DistributionFamily::beta, "alpha, beta, min, max", 4, false}}};

    std::string
    family_list()
    {
      std::string text;
      for (const auto &[name, syntax] : families)
        text += (text.empty() ? "" : ", ") + name + "(" + syntax.arguments +
                (syntax.may_truncate ? "[, min, max]" : "") + ")";
      return text;
    }

    /** Lower case with runs of blanks as one space. */
    std::string
    normalised_name(const std::string &text)
    {
      std::string name;
      for (const char c : trimmed(text))
        if (std::isspace(static_cast<unsigned char>(c)))
          {
            if (!name.empty() && name.back() != ' ')
              name += ' ';
          }
        else
          name +=
            static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return name;
    }

    [[noreturn]] void
    refuse_input(const std::string &entry, const std::string &allowed)
    {
      throw InputError(inputs_parameter, entry, allowed);
    }

    /** The checks of one family's arguments that do not need the scene. */
    void
    check_arguments(const UncertainInput &input)
    {
      const std::vector<double> &a = input.arguments;
      const auto bounds_in_order   = [&](double low, double high) {
        if (!(low < high))
          refuse_input(input.text,
                       "bounds in increasing order: min = " + number(low) +
                         " must be below max = " + number(high));
      };
      switch (input.family)
        {
          case DistributionFamily::normal:
          case DistributionFamily::lognormal:
            if (!(a[1] > 0))
              refuse_input(input.text,
                           "a standard deviation sd > 0 (sd = " + number(a[1]) +
                             " here), in the parameter's units");
            if (input.family == DistributionFamily::lognormal && !(a[0] > 0))
              refuse_input(input.text,
                           "a lognormal mean > 0 (mean = " + number(a[0]) +
                             " here): a lognormal value is positive");
            if (input.truncated())
              bounds_in_order(a[2], a[3]);
            if (input.family == DistributionFamily::lognormal &&
                input.truncated() && !(a[3] > 0))
              refuse_input(input.text,
                           "a truncation max > 0 (max = " + number(a[3]) +
                             " here): a lognormal value is positive");
            break;
          case DistributionFamily::uniform:
            bounds_in_order(a[0], a[1]);
            break;
          case DistributionFamily::triangular:
            bounds_in_order(a[0], a[2]);
            if (!(a[0] <= a[1] && a[1] <= a[2]))
              refuse_input(input.text,
                           "min <= mode <= max (mode = " + number(a[1]) +
                             " here)");
            break;
          case DistributionFamily::beta:
            if (!(a[0] > 0 && a[1] > 0))
              refuse_input(input.text,
                           "shape exponents alpha > 0 and beta > 0 (alpha = " +
                             number(a[0]) + ", beta = " + number(a[1]) +
                             " here)");
            bounds_in_order(a[2], a[3]);
            break;
        }
    }

    UncertainInput
    parse_input(const std::string &entry)
    {
      const auto colon = entry.rfind(':');
      if (colon == std::string::npos)
        refuse_input(entry,
                     "entries \"Subsection/Entry: family(arguments)\" "
                     "separated by ';', e.g. \"Joints/Bedding friction "
                     "angle: normal(30, 3, 15, 45)\"");
      UncertainInput input;
      input.text = entry;
      input.path = trimmed(entry.substr(0, colon));
      if (input.path.find('/') == std::string::npos)
        refuse_input(entry,
                     "a parameter path \"Subsection/Entry\" before ':' (got '" +
                       input.path + "')");

      const std::string law   = trimmed(entry.substr(colon + 1));
      const auto        open  = law.find('(');
      const auto        close = law.rfind(')');
      if (open == std::string::npos || close == std::string::npos ||
          close < open || !trimmed(law.substr(close + 1)).empty())
        refuse_input(entry,
                     "a distribution family(arguments) after ':', one of " +
                       family_list());
      const std::string name = normalised_name(law.substr(0, open));
      const auto        family =
        std::find_if(families.begin(), families.end(), [&](const auto &f) {
          return f.first == name;
        });
      if (family == families.end())
        refuse_input(entry,
                     "a distribution family among " + family_list() +
                       " (got '" + name + "')");
      const FamilySyntax &syntax = family->second;
      input.family               = syntax.family;

      const std::vector<std::string> arguments =
        pieces(law.substr(open + 1, close - open - 1), ',');
      const bool count_fits =
        arguments.size() == syntax.n_required ||
        (syntax.may_truncate && arguments.size() == syntax.n_required + 2);
      if (!count_fits)
        refuse_input(entry,
                     name + "(" + syntax.arguments +
                       (syntax.may_truncate ? "[, min, max]" : "") +
                       "): " + std::to_string(syntax.n_required) + " numbers" +
                       (syntax.may_truncate ?
                          " or, truncated, " +
                            std::to_string(syntax.n_required + 2) :
                          "") +
                       ", got " + std::to_string(arguments.size()));
      for (const std::string &argument : arguments)
        {
          double value = 0;
          if (!read_number(argument, value))
            refuse_input(entry,
                         "finite numbers as the arguments of " + name + "(" +
                           syntax.arguments + ") (got '" + argument + "')");
          input.arguments.push_back(value);
        }
      check_arguments(input);
      return input;
    }
  } // namespace

  bool
  UncertainInput::truncated() const
  {
    return (family == DistributionFamily::normal ||
            family == DistributionFamily::lognormal) &&
           arguments.size() == 4;
  }

  std::pair<double, double>
  UncertainInput::support() const
  {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    switch (family)
      {
        case DistributionFamily::normal:
          return truncated() ? std::pair{arguments[2], arguments[3]} :
                               std::pair{-infinity, infinity};
        case DistributionFamily::lognormal:
          return truncated() ?
                   std::pair{std::max(arguments[2], 0.), arguments[3]} :
                   std::pair{0., infinity};
        case DistributionFamily::uniform:
          return {arguments[0], arguments[1]};
        case DistributionFamily::triangular:
          return {arguments[0], arguments[2]};
        case DistributionFamily::beta:
          return {arguments[2], arguments[3]};
      }
    return {-infinity, infinity};
  }

  double
  UncertainInput::typical_value() const
  {
    const auto [low, high] = support();
    switch (family)
      {
        case DistributionFamily::normal:
        case DistributionFamily::lognormal:
          return std::clamp(arguments[0], low, high);
        case DistributionFamily::triangular:
          return arguments[1];
        case DistributionFamily::uniform:
        case DistributionFamily::beta:
          return 0.5 * (low + high);
      }
    return arguments[0];
  }

  std::vector<UncertainInput>
  parse_uncertain_inputs(const std::string &text)
  {
    std::vector<UncertainInput> inputs;
    std::set<std::string>       paths;
    for (const std::string &entry : pieces(text, ';'))
      {
        inputs.push_back(parse_input(entry));
        if (!paths.insert(inputs.back().path).second)
          refuse_input(entry,
                       "each parameter once; " + inputs.back().path +
                         " is given twice");
      }
    return inputs;
  }

  std::vector<InputCorrelation>
  parse_input_correlations(const std::string                 &text,
                           const std::vector<UncertainInput> &inputs)
  {
    std::set<std::string> uncertain;
    for (const auto &input : inputs)
      uncertain.insert(input.path);

    std::vector<InputCorrelation>                 correlations;
    std::set<std::pair<std::string, std::string>> pairs;
    for (const std::string &entry : pieces(text, ';'))
      {
        const auto refuse = [&](const std::string &allowed) {
          throw InputError(correlations_parameter, entry, allowed);
        };
        const auto colon = entry.rfind(':');
        const auto comma = entry.find(',');
        if (colon == std::string::npos || comma == std::string::npos ||
            comma > colon)
          refuse("entries \"Subsection/Entry, Subsection/Entry: value\" "
                 "separated by ';'");
        InputCorrelation correlation;
        correlation.text  = entry;
        correlation.first = trimmed(entry.substr(0, comma));
        correlation.second =
          trimmed(entry.substr(comma + 1, colon - comma - 1));
        for (const std::string &path : {correlation.first, correlation.second})
          if (uncertain.count(path) == 0)
            refuse("paths of Uncertainty/Inputs; '" + path +
                   "' is not one of them");
        if (correlation.first == correlation.second)
          refuse("two different inputs");
        if (!read_number(entry.substr(colon + 1), correlation.value) ||
            !(correlation.value > -1 && correlation.value < 1))
          refuse("a correlation strictly between -1 and 1 after ':'");
        const auto pair = std::minmax(correlation.first, correlation.second);
        if (!pairs.insert({pair.first, pair.second}).second)
          refuse("each pair once; " + pair.first + ", " + pair.second +
                 " is given twice");
        correlations.push_back(correlation);
      }
    return correlations;
  }

  std::string
  to_string(const DistributionFamily family)
  {
    switch (family)
      {
        case DistributionFamily::normal:
          return "normal";
        case DistributionFamily::lognormal:
          return "lognormal";
        case DistributionFamily::uniform:
          return "uniform";
        case DistributionFamily::triangular:
          return "triangular";
        case DistributionFamily::beta:
          return "beta";
      }
    return "?";
  }
} // namespace FloorBlock::Parameters
