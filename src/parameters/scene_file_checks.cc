#include <common/input_error.h>
#include <parameters/scene_file_checks.h>

#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <filesystem>
#include <regex>
#include <sstream>

namespace FloorBlock::Parameters
{
  namespace
  {
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

    /** Throws at the first node with an empty key, depth first. */
    void
    reject_unnamed_nodes(const std::string &                 path,
                         const boost::property_tree::ptree &node,
                         const std::string &                 location)
    {
      for (const auto &[name, child] : node)
        {
          if (name.empty())
            throw InputError(
              path + ": a node without a name in " +
              (location.empty() ? std::string("the top level") :
                                  "'" + location + "'") +
              " (a JSON array, or a member named \"\"): a scene file "
              "nests named subsections and entries only, e.g. "
              "{\"Geometry\": {\"Number of blocks\": {\"value\": \"6\"}}}");
          reject_unnamed_nodes(path,
                               child,
                               location.empty() ? name :
                                                  location + "/" + name);
        }
    }

    void
    reject_unnamed_nodes(const std::string &path,
                         const std::string &text,
                         const std::string &extension)
    {
      boost::property_tree::ptree tree;
      std::istringstream          in(text);
      try
        {
          if (extension == ".json")
            boost::property_tree::read_json(in, tree);
          else
            boost::property_tree::read_xml(in, tree);
        }
      catch (const boost::property_tree::ptree_error &)
        {
          return; // a syntax error: deal.II's reader names it
        }
      reject_unnamed_nodes(path, tree, "");
    }
  } // namespace

  void
  check_scene_file_text(const std::string &path, const std::string &text)
  {
    const std::string extension = std::filesystem::path(path).extension();
    if (extension == ".prm")
      reject_include_statements(path, text);
    else if (extension == ".json" || extension == ".xml")
      reject_unnamed_nodes(path, text, extension);
  }
} // namespace FloorBlock::Parameters
