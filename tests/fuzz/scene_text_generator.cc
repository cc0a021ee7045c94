#include "scene_text_generator.h"

#include <parameters/scenario_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <regex>
#include <sstream>

namespace FloorBlock::Fuzz
{
  namespace
  {
    // Mix of input kinds, in InputKind order: mostly inputs close to a valid
    // scene (they reach the closed forms), some far from it (they exercise
    // the parser's error paths).
    constexpr std::array<double, n_input_kinds> kind_weights = {
      {1., 30., 30., 15., 8., 8., 8.}};

    // Deeper than any real scene (two levels), shallow enough to stay far
    // below the stack limits of the recursive JSON/XML readers.
    constexpr unsigned int deepest_nesting = 40;

    /** The declared parameters as deal.II prints them in the given style. */
    std::string
    printed_parameters(const dealii::ParameterHandler::OutputStyle style)
    {
      dealii::ParameterHandler prm;
      Parameters::ScenarioParameters::declare_parameters(prm);
      std::ostringstream text;
      prm.print_parameters(text, style);
      return text.str();
    }

    std::vector<std::string>
    split_lines(const std::string &text)
    {
      std::vector<std::string> lines;
      std::istringstream       stream(text);
      std::string              line;
      while (std::getline(stream, line))
        lines.push_back(line);
      return lines;
    }

    std::string
    set_line(const std::string &name, const std::string &value)
    {
      return "  set " + name + " = " + value + "\n";
    }

    /** A value of a random JSON type, most often a hostile string. */
    nlohmann::json
    random_json_value(RandomEngine &engine)
    {
      switch (random_index(engine, 8))
        {
          case 0:
            return nullptr;
          case 1:
            return std::uniform_real_distribution<double>(-1e3, 1e3)(engine);
          case 2:
            return random_chance(engine, 0.5);
          case 3:
            return nlohmann::json::array({random_value(engine), 1});
          case 4:
            return nlohmann::json::object({{"value", random_value(engine)}});
          default:
            return random_value(engine);
        }
    }

    /** Replaces or drops leaves of deal.II's JSON description at random. */
    void
    randomize_json(RandomEngine &engine, nlohmann::json &node)
    {
      if (!node.is_object())
        return;
      for (auto &[key, child] : node.items())
        {
          if (key == "value" && random_chance(engine, 0.1))
            child = random_json_value(engine);
          else
            randomize_json(engine, child);
        }
      if (random_chance(engine, 0.05))
        node.erase(node.begin());
      if (random_chance(engine, 0.05))
        node[random_value(engine)] = random_json_value(engine);
    }

    std::string
    nested_text(RandomEngine      &engine,
                const std::string &open,
                const std::string &close)
    {
      const std::size_t depth = 1 + random_index(engine, deepest_nesting);
      std::string       text;
      for (std::size_t level = 0; level < depth; ++level)
        text += open;
      for (std::size_t level = 0; level < depth; ++level)
        text += close;
      return text;
    }
  } // namespace

  namespace
  {
    /**
     * Log-uniform in [lowest, highest] for ranges over many decades, so that
     * small values (thin fillets, few loaded blocks) occur as often as large
     * ones; a range starting at 0 is treated as starting six decades below
     * its top. Signed ranges fall back to uniform.
     */
    double
    log_uniform(RandomEngine &engine, const double lowest, const double highest)
    {
      constexpr double decades_below_top_for_zero = 1e-6;
      const double     bottom =
        lowest > 0. ? lowest : highest * decades_below_top_for_zero;
      if (lowest < 0. || !(highest > bottom))
        return std::uniform_real_distribution<double>(lowest, highest)(engine);
      return std::exp(
        std::uniform_real_distribution<double>(std::log(bottom),
                                               std::log(highest))(engine));
    }
  } // namespace

  std::string
  in_range_value(RandomEngine &engine, const DeclaredParameter &parameter)
  {
    static const std::regex number_range(
      R"(\[(Double|Integer range) ([-+0-9.e]+)\.\.\.([-+0-9.e]+) )");
    static const std::regex selection(R"(^\[Selection ([^ ]*) \]$)");
    static const std::regex integer_list(
      R"(^\[List of <\[Integer range ([0-9]+)\.\.\.([0-9]+) .*> of length ([0-9]+)\.\.\.([0-9]+) )");
    std::smatch        match;
    std::ostringstream value;
    value.precision(17);
    if (std::regex_search(parameter.pattern, match, integer_list))
      {
        // A few distinct entries: real scenes load a handful of blocks.
        const double lowest  = std::stod(match[1]),
                     highest = std::stod(match[2]);
        const std::size_t length =
          std::stoul(match[3]) + random_index(engine, 4);
        for (std::size_t i = 0; i < length; ++i)
          value << (i > 0 ? "," : "")
                << std::lround(log_uniform(engine, lowest, highest));
      }
    else if (std::regex_search(parameter.pattern, match, number_range))
      {
        const double lowest  = std::stod(match[2]),
                     highest = std::stod(match[3]);
        const bool integer   = match[1] == "Integer range";
        double     number;
        // Range ends exactly; a zero lower end often (a sharp corner, no
        // cohesion: values the cross-parameter checks always allow).
        if (random_chance(engine, lowest == 0. ? 0.3 : 0.1))
          number =
            random_chance(engine, lowest == 0. ? 0.8 : 0.5) ? lowest : highest;
        else if (random_chance(engine, 0.5))
          number =
            std::uniform_real_distribution<double>(lowest, highest)(engine);
        else
          number = log_uniform(engine, lowest, highest);
        if (integer)
          value << std::lround(number);
        else
          value << std::min(std::max(number, lowest), highest);
      }
    else if (std::regex_search(parameter.pattern, match, selection))
      {
        std::vector<std::string> choices;
        std::istringstream       words(match[1].str());
        for (std::string word; std::getline(words, word, '|');)
          choices.push_back(word);
        value << choices[random_index(engine, choices.size())];
      }
    else if (parameter.pattern == "[Bool]")
      value << (random_chance(engine, 0.5) ? "true" : "false");
    else
      value << parameter.default_value;
    return value.str();
  }

  std::vector<DeclaredParameter>
  declared_parameters()
  {
    const auto tree =
      nlohmann::json::parse(printed_parameters(dealii::ParameterHandler::JSON));
    std::vector<DeclaredParameter> parameters;
    for (const auto &[subsection, entries] : tree.items())
      for (const auto &[name, entry] : entries.items())
        if (entry.contains("value"))
          parameters.push_back({dealii::Utilities::trim(subsection),
                                dealii::Utilities::trim(name),
                                entry["value"].get<std::string>(),
                                entry.value("pattern_description", "")});
    return parameters;
  }

  std::string
  to_string(const InputKind kind)
  {
    const std::array<const char *, n_input_kinds> names = {{"default_scene",
                                                            "replaced_values",
                                                            "every_parameter",
                                                            "byte_mutation",
                                                            "random_structure",
                                                            "json_scene",
                                                            "xml_scene"}};
    return names[static_cast<unsigned int>(kind)];
  }

  SceneTextGenerator::SceneTextGenerator(const std::string &valid_scene_text)
    : valid_text(valid_scene_text)
    , valid_lines(split_lines(valid_scene_text))
    , parameters(declared_parameters())
  {}

  SceneInput
  SceneTextGenerator::next(RandomEngine &engine) const
  {
    std::discrete_distribution<unsigned int> kinds(kind_weights.begin(),
                                                   kind_weights.end());
    SceneInput                               input;
    input.kind      = static_cast<InputKind>(kinds(engine));
    input.extension = ".prm";
    switch (input.kind)
      {
        case InputKind::default_scene:
          input.text = valid_text;
          break;
        case InputKind::replaced_values:
          input.text = replaced_values(engine);
          break;
        case InputKind::every_parameter:
          input.text = every_parameter(engine);
          break;
        case InputKind::byte_mutation:
          input.text = byte_mutation(engine, valid_text);
          break;
        case InputKind::random_structure:
          input.text = random_structure(engine);
          break;
        case InputKind::json_scene:
          input.text      = json_scene(engine);
          input.extension = ".json";
          break;
        case InputKind::xml_scene:
          input.text      = xml_scene(engine);
          input.extension = ".xml";
          break;
      }
    if (random_chance(engine, 0.3))
      input.overrides = overrides(engine);
    return input;
  }

  std::string
  SceneTextGenerator::value_for(RandomEngine            &engine,
                                const DeclaredParameter &parameter) const
  {
    // Half valid by pattern (such scenes reach the closed forms), the rest
    // hostile or the default.
    const double draw = std::uniform_real_distribution<double>(0., 1.)(engine);
    if (draw < 0.5)
      return in_range_value(engine, parameter);
    return draw < 0.85 ? random_value(engine) : parameter.default_value;
  }

  std::string
  SceneTextGenerator::replaced_values(RandomEngine &engine) const
  {
    // One to three entries of the valid scene get hostile values; the rest
    // stays valid, so the scene often reaches the closed forms.
    std::string       text           = valid_text;
    const std::size_t n_replacements = 1 + random_index(engine, 3);
    for (std::size_t i = 0; i < n_replacements; ++i)
      {
        const auto &parameter =
          parameters[random_index(engine, parameters.size())];
        text += "subsection " + parameter.subsection + "\n" +
                set_line(parameter.name, value_for(engine, parameter)) +
                "end\n";
      }
    return text;
  }

  std::string
  SceneTextGenerator::every_parameter(RandomEngine &engine) const
  {
    std::string text;
    std::string open_subsection;
    for (const auto &parameter : parameters)
      {
        if (parameter.subsection != open_subsection)
          {
            text += (open_subsection.empty() ? "" : "end\n") +
                    std::string("subsection ") + parameter.subsection + "\n";
            open_subsection = parameter.subsection;
          }
        // Mostly valid random values: most scenes pass the patterns and
        // probe the closed forms over the whole declared ranges.
        text += set_line(parameter.name,
                         random_chance(engine, 0.97) ?
                           in_range_value(engine, parameter) :
                           value_for(engine, parameter));
      }
    return text + "end\n";
  }

  std::string
  SceneTextGenerator::byte_mutation(RandomEngine      &engine,
                                    const std::string &text) const
  {
    std::string       mutated = text;
    const std::size_t n_edits = 1 + random_index(engine, 8);
    for (std::size_t edit = 0; edit < n_edits; ++edit)
      {
        const std::size_t at     = random_index(engine, mutated.size() + 1);
        const std::size_t length = random_index(engine, 16);
        switch (random_index(engine, 5))
          {
            case 0:
              mutated.erase(at, length);
              break;
            case 1:
              mutated.insert(at, random_bytes(engine, length));
              break;
            case 2:
              mutated.insert(at, mutated.substr(at, 4 * length));
              break;
            case 3:
              if (at < mutated.size())
                mutated[at] = static_cast<char>(mutated[at] ^
                                                (1 << random_index(engine, 8)));
              break;
            default:
              mutated.insert(
                at,
                valid_lines[random_index(engine, valid_lines.size())] + "\n");
          }
      }
    return mutated;
  }

  std::string
  SceneTextGenerator::random_structure(RandomEngine &engine) const
  {
    // Lines drawn from the grammar's pieces in random order and nesting:
    // unknown and nested subsections, missing and extra "end", stray text.
    std::string       text;
    const std::size_t n_lines = random_index(engine, 60);
    for (std::size_t line = 0; line < n_lines; ++line)
      {
        const auto &parameter =
          parameters[random_index(engine, parameters.size())];
        switch (random_index(engine, 8))
          {
            case 7:
              // Harmless targets only: the dangerous ones (the scene itself,
              // /dev/zero) are SceneFuzz.IncludeStatementsAreRejected.
              text +=
                std::string(random_chance(engine, 0.5) ? "include " :
                                                         "INCLUDE ") +
                (random_chance(engine, 0.5) ? "/nonexistent.prm" : "/tmp") +
                "\n";
              break;
            case 0:
              text += "subsection " + parameter.subsection + "\n";
              break;
            case 1:
              text += "subsection " + random_value(engine) + "\n";
              break;
            case 2:
              text += "end\n";
              break;
            case 3:
              text += "set " + random_value(engine) + " = " +
                      random_value(engine) + "\n";
              break;
            case 4:
              text += random_value(engine) + "\n";
              break;
            default:
              text += set_line(parameter.name, value_for(engine, parameter));
          }
      }
    return text;
  }

  std::string
  SceneTextGenerator::json_scene(RandomEngine &engine) const
  {
    switch (random_index(engine, 4))
      {
        case 0:
          return nested_text(engine, "[", "]");
        case 1:
          return nested_text(engine, "{\"a\":", "}");
        default:
          break;
      }
    auto tree =
      nlohmann::json::parse(printed_parameters(dealii::ParameterHandler::JSON));
    // Valid values by pattern, then structural damage at random.
    for (const auto &parameter : parameters)
      tree[parameter.subsection][parameter.name]["value"] =
        random_chance(engine, 0.97) ? in_range_value(engine, parameter) :
                                      value_for(engine, parameter);
    if (random_chance(engine, 0.3))
      randomize_json(engine, tree);
    // Invalid UTF-8 from random values is dropped here; byte edits below
    // bring raw bytes back.
    const std::string text = tree.dump(random_chance(engine, 0.5) ? 2 : -1,
                                       ' ',
                                       false,
                                       nlohmann::json::error_handler_t::ignore);
    return random_chance(engine, 0.4) ? byte_mutation(engine, text) : text;
  }

  std::string
  SceneTextGenerator::xml_scene(RandomEngine &engine) const
  {
    if (random_chance(engine, 0.1))
      return nested_text(engine, "<a>", "</a>");
    // Raw (unescaped) random values between <value> tags: sometimes valid
    // values, sometimes broken XML.
    std::string       text = printed_parameters(dealii::ParameterHandler::XML);
    const std::string open = "<value>", close = "</value>";
    for (std::size_t start = text.find(open); start != std::string::npos;
         start             = text.find(open, start + 1))
      {
                    const std::size_t end = text.find(close, start);
                    if (end != std::string::npos && random_chance(engine, 0.1))
          text.replace(start + open.size(),
                       end - start - open.size(),
                       random_value(engine));
      }
    return random_chance(engine, 0.4) ? byte_mutation(engine, text) : text;
  }

  std::vector<std::string>
  SceneTextGenerator::overrides(RandomEngine &engine) const
  {
    std::vector<std::string> assignments;
    const std::size_t        n_assignments = 1 + random_index(engine, 3);
    for (std::size_t i = 0; i < n_assignments; ++i)
      {
        const auto &parameter =
          parameters[random_index(engine, parameters.size())];
        switch (random_index(engine, 4))
          {
            case 0:
              assignments.push_back(random_value(engine));
              break;
            case 1:
              assignments.push_back(random_value(engine) + "/" +
                                    random_value(engine) + "=" +
                                    random_value(engine));
              break;
            default:
              assignments.push_back(parameter.subsection + "/" +
                                    parameter.name + "=" +
                                    value_for(engine, parameter));
          }
      }
    return assignments;
  }
} // namespace FloorBlock::Fuzz
