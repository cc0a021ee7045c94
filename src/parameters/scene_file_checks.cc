#include <common/input_error.h>
#include <parameters/scene_file_checks.h>

#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <algorithm>
#include <cctype>
#include <regex>
#include <sstream>
#include <vector>

namespace FloorBlock::Parameters
{
  namespace
  {
    using PropertyTree = boost::property_tree::ptree;

    void
    reject_include_statements(const std::string &path, const std::string &text)
    {
      // Lines ending in a backslash are joined first, as deal.II joins them.
      const std::string joined =
        std::regex_replace(text, std::regex(R"(\\[ \t]*\r?\n)"), "");
      std::istringstream lines(joined);
      for (std::string line; std::getline(lines, line);)
        {
          line = dealii::Utilities::trim(line.substr(0, line.find('#')));
          if (line.rfind("include", 0) == 0 || line.rfind("INCLUDE", 0) == 0)
            throw InputError(path + ": 'include' statements are not "
                                    "supported; a scene file must be "
                                    "self-contained");
        }
    }

    /** What deal.II's demangle can read: each '_' starts "_xx", x in 0-9a-f. */
    bool
    has_only_valid_escapes(const std::string &name)
    {
      const auto is_hex_digit = [](const char c) {
        return std::isdigit(static_cast<unsigned char>(c)) ||
               (c >= 'a' && c <= 'f');
      };
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_')
          {
            if (i + 2 >= name.size() || !is_hex_digit(name[i + 1]) ||
                !is_hex_digit(name[i + 2]))
              return false;
            i += 2;
          }
      return true;
    }

    std::string
    location_text(const std::vector<std::string> &subsections)
    {
      if (subsections.empty())
        return "the top level";
      std::string text;
      for (const std::string &name : subsections)
        text += (text.empty() ? "" : "/") + name;
      return "'" + text + "'";
    }

    /**
     * Checks every name deal.II's read_xml_recursively passes to demangle,
     * walking the levels it walks; @p subsections is the way down, for the
     * message (built only when it throws: the nesting can be deep).
     */
    void
    check_names(const std::string        &path,
                const PropertyTree       &node,
                std::vector<std::string> &subsections)
    {
      for (const auto &[name, child] : node)
        {
          if (name.empty())
            throw InputError(
              path + ": a node without a name in " +
              location_text(subsections) +
              " (a JSON array, or a member named \"\"): a scene file nests "
              "named subsections and entries only, e.g. "
              "{\"Geometry\": {\"Number of blocks\": \"6\"}}");
          if (!has_only_valid_escapes(name))
            throw InputError(
              path + ": the name '" + name + "' in " +
              location_text(subsections) +
              " has an '_' that is not deal.II's escape '_' + two lowercase "
              "hex digits (e.g. \"Number_20of_20blocks\"); write other "
              "characters as such an escape");
          const bool is_entry = child.get_child_optional("value") ||
                                child.get_child_optional("alias");
          if (!is_entry)
            {
              subsections.push_back(name);
              check_names(path, child, subsections);
              subsections.pop_back();
            }
        }
    }

    /**
     * Deepest nesting of JSON arrays/objects or XML elements, read from the
     * raw text (strings, comments and declarations skipped); XML attribute
     * values holding '>' can make it inexact, which a limit far above any
     * scene's depth absorbs.
     */
    unsigned int
    nesting_depth(const std::string &text, const std::string &type)
    {
      unsigned int depth = 0, deepest = 0;
      if (type == "json")
        {
          bool in_string = false;
          for (std::size_t i = 0; i < text.size(); ++i)
            {
              const char c = text[i];
              if (in_string)
                {
                  if (c == '\\')
                    ++i;
                  else if (c == '"')
                    in_string = false;
                }
              else if (c == '"')
                in_string = true;
              else if (c == '[' || c == '{')
                deepest = std::max(deepest, ++depth);
              else if ((c == ']' || c == '}') && depth > 0)
                --depth;
            }
          return deepest;
        }
      for (std::size_t start = text.find('<'); start != std::string::npos;
           start             = text.find('<', start + 1))
        {
                      const std::size_t end = text.find('>', start);
                      if (end == std::string::npos || start + 1 >= text.size())
            break;
          const char next = text[start + 1];
                      if (next == '/')
            depth = depth > 0 ? depth - 1 : 0;
          else if (next != '?' && next != '!' && text[end - 1] != '/')
            deepest = std::max(deepest, ++depth);
        }
      return deepest;
    }

    void
    check_tree_names(const std::string &path,
                     const std::string &text,
                     const std::string &type)
    {
      // A scene nests subsection, entry and value: a handful of levels.
      // Boost's parsers recurse once per level and overflow the stack long
      // before 1e5 levels (a crash, measured), so deeper text is refused
      // before they read it.
      constexpr unsigned int deepest_allowed = 100;
      const unsigned int     depth           = nesting_depth(text, type);
      if (depth > deepest_allowed)
        throw InputError(path + ": nested " + std::to_string(depth) +
                         " levels deep; a scene file nests at most " +
                         std::to_string(deepest_allowed) +
                         " (subsections, entries and values need a few)");

      PropertyTree       tree;
      std::istringstream in(text);
      try
        {
          if (type == "json")
            boost::property_tree::read_json(in, tree);
          else
            boost::property_tree::read_xml(in, tree);
        }
      catch (const boost::property_tree::ptree_error &)
        {
          return; // a syntax error: deal.II's reader names it
        }
      std::vector<std::string> subsections;
      check_names(path, tree, subsections);
    }

    /** The file type as ParameterHandler::parse_input picks it. */
    std::string
    file_type(const std::string &path)
    {
      std::string type = path.substr(path.find_last_of('.') + 1);
      std::transform(type.begin(), type.end(), type.begin(), [](const char c) {
        return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      });
      return type;
    }
  } // namespace

  void
  check_scene_file_text(const std::string &path, const std::string &text)
  {
    const std::string type = file_type(path);
    if (type == "prm")
      reject_include_statements(path, text);
    else if (type == "json" || type == "xml")
      check_tree_names(path, text, type);
  }
} // namespace FloorBlock::Parameters
