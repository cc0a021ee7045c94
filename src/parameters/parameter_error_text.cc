#include <parameters/parameter_error_text.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
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

    /** Levenshtein distance, ignoring case: letters to add, drop or change. */
    std::size_t
    edit_distance(const std::string &from, const std::string &to)
    {
      std::vector<std::size_t> previous(to.size() + 1), current(to.size() + 1);
      for (std::size_t j = 0; j <= to.size(); ++j)
        previous[j] = j;
      for (std::size_t i = 1; i <= from.size(); ++i)
        {
          current[0] = i;
          for (std::size_t j = 1; j <= to.size(); ++j)
            {
              const bool same =
                std::tolower(from[i - 1]) == std::tolower(to[j - 1]);
              current[j] = std::min({previous[j] + 1,
                                     current[j - 1] + 1,
                                     previous[j - 1] + (same ? 0 : 1)});
            }
          std::swap(previous, current);
        }
      return previous[to.size()];
    }

    std::string
    lower_case(std::string text)
    {
      for (char &letter : text)
        letter = std::tolower(letter);
      return text;
    }

    /** The text between @p opening and the next '>' after it, or "". */
    std::string
    bracketed_after(const std::string &text, const std::string &opening)
    {
      const auto start = text.find(opening);
      if (start == std::string::npos)
        return "";
      const auto first = start + opening.size();
      const auto end   = text.find('>', first);
      return end == std::string::npos ? "" : text.substr(first, end - first);
    }

    /** The number N of "Line <N>" in a deal.II parse message, 0 if none. */
    unsigned int
    line_of(const std::string &message)
    {
      const std::string number = bracketed_after(message, "Line <");
      return number.empty() ? 0u : std::stoul(number);
    }

    struct OpenSubsection
    {
      std::string  name;
      unsigned int line;
    };

    /** The subsections still open before line @p before_line of @p text. */
    std::vector<OpenSubsection>
    open_subsections(const std::string &text, const unsigned int before_line)
    {
      std::vector<OpenSubsection> open;
      std::istringstream          lines(text);
      std::string                 line;
      for (unsigned int number = 1;
           std::getline(lines, line) && number < before_line;
           ++number)
        {
          std::string        content = line.substr(0, line.find('#'));
          std::istringstream words(content);
          std::string        keyword;
          words >> keyword;
          if (keyword == "subsection")
            {
              std::string name;
              std::getline(words, name);
              open.push_back({fold_whitespace(name), number});
            }
          else if (keyword == "end" && !open.empty())
            open.pop_back();
        }
      return open;
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

  namespace
  {
    /**
     * Calls @p visit(path, documentation) for every entry of @p prm, from
     * the parameter file deal.II prints, where each entry's documentation
     * stands as comments above its `set` line.
     */
    template <typename Visit>
    void
    for_each_entry(const dealii::ParameterHandler &prm, Visit &&visit)
    {
      std::ostringstream text;
      prm.print_parameters(text, dealii::ParameterHandler::PRM);
      std::istringstream       lines(text.str());
      std::string              line, comment;
      std::vector<std::string> open;
      while (std::getline(lines, line))
        {
          const std::string trimmed = dealii::Utilities::trim(line);
          if (trimmed.rfind("#", 0) == 0)
            comment += " " + dealii::Utilities::trim(trimmed.substr(1));
          else if (trimmed.rfind("subsection ", 0) == 0)
            {
              open.push_back(dealii::Utilities::trim(trimmed.substr(11)));
              comment.clear();
            }
          else if (trimmed == "end" && !open.empty())
            open.pop_back();
          else if (trimmed.rfind("set ", 0) == 0)
            {
              std::string path;
              for (const std::string &subsection : open)
                path += subsection + "/";
              visit(path + dealii::Utilities::trim(
                             trimmed.substr(4, trimmed.find('=') - 4)),
                    comment);
              comment.clear();
            }
        }
    }
  } // namespace

  std::vector<std::string>
  entry_paths(const dealii::ParameterHandler &prm)
  {
    std::vector<std::string> paths;
    for_each_entry(prm, [&](const std::string &path, const std::string &) {
      paths.push_back(path);
    });
    return paths;
  }

  std::map<std::string, std::string>
  entry_units(const dealii::ParameterHandler &prm)
  {
    std::map<std::string, std::string> units;
    for_each_entry(prm,
                   [&](const std::string &path, const std::string &comment) {
                     const auto  start = comment.rfind("Units: ");
                     std::string unit  = start == std::string::npos ?
                                           "" :
                                           comment.substr(start + 7);
                     if (!unit.empty() && unit.back() == '.')
                       unit.pop_back();
                     units[path] = dealii::Utilities::trim(unit);
                   });
    return units;
  }

  std::vector<std::string>
  nearest_names(const std::string              &name,
                const std::vector<std::string> &declared_paths)
  {
    // Compare with the entry's own name: the user's subsection may be the
    // wrong one as well.
    const std::string wanted = lower_case(name.substr(name.rfind('/') + 1));
    const std::size_t largest_distance =
      std::max<std::size_t>(2, wanted.size() / 3);
    std::vector<std::pair<std::size_t, std::string>> ranked;
    for (const std::string &path : declared_paths)
      {
        const std::string entry = lower_case(path.substr(path.rfind('/') + 1));
        const std::size_t distance = edit_distance(wanted, entry);
        // A name the user shortened or lengthened ("Loaded blocks" for
        // "Loaded blocks from face") is near whatever the letter count.
        const bool contained = entry.find(wanted) != std::string::npos ||
                               wanted.find(entry) != std::string::npos;
        if (distance <= largest_distance || contained)
          ranked.push_back({contained ? 0 : distance, path});
      }
    std::stable_sort(ranked.begin(),
                     ranked.end(),
                     [](const auto &a, const auto &b) {
                       return a.first < b.first;
                     });
    constexpr std::size_t    most_suggestions = 3;
    std::vector<std::string> nearest;
    for (const auto &[distance, path] : ranked)
      if (nearest.size() < most_suggestions)
        nearest.push_back(path);
    return nearest;
  }

  std::string
  parse_error_hint(const std::string              &message,
                   const std::string              &file_text,
                   const std::vector<std::string> &declared_paths)
  {
    std::string unknown = bracketed_after(message, "No entry with name <");
    if (unknown.empty())
      unknown = bracketed_after(message, "You can't ask for entry <");
    if (!unknown.empty())
      {
        const std::vector<std::string> nearest =
          nearest_names(unknown, declared_paths);
        std::string hint = " '" + unknown + "' is not a parameter";
        if (!nearest.empty())
          {
            hint += "; did you mean ";
            for (std::size_t k = 0; k < nearest.size(); ++k)
              hint += (k == 0                  ? "" :
                       k + 1 == nearest.size() ? " or " :
                                                 ", ") +
                      nearest[k];
            hint += "?";
          }
        return hint + " (`floorblock print-parameters` lists every name)";
      }

    const bool no_subsection =
      message.find("no such subsection to be entered") != std::string::npos;
    const bool unbalanced =
      message.find("unequal numbers of 'subsection' and 'end'") !=
      std::string::npos;
    if (!no_subsection && !unbalanced)
      return "";
    const unsigned int line =
      no_subsection ? line_of(message) : static_cast<unsigned int>(-1);
    const std::vector<OpenSubsection> open = open_subsections(file_text, line);
    if (open.empty())
      return no_subsection ? " That subsection is not declared at the top "
                             "level (`floorblock print-parameters` lists "
                             "the subsections)" :
                             "";
    // The innermost subsection still open: the one the misplaced line sits
    // in (no_subsection) or the one the file never closes (unbalanced).
    const OpenSubsection &innermost = open.back();
    if (no_subsection)
      return " Subsection '" + innermost.name + "' opened at line " +
             std::to_string(innermost.line) + " is still open at line " +
             std::to_string(line) + ": add `end` before line " +
             std::to_string(line) + " to close it";
    return " Subsection '" + innermost.name + "' opened at line " +
           std::to_string(innermost.line) +
           " is never closed: add `end` after its last entry";
  }
} // namespace FloorBlock::Parameters
