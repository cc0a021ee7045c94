#pragma once

#include <string>
#include <vector>

#include "random_values.h"

namespace FloorBlock::Fuzz
{
  /** One declared scene parameter, as ParameterHandler knows it. */
  struct DeclaredParameter
  {
    std::string subsection;    ///< "Geometry"
    std::string name;          ///< "Number of blocks"
    std::string default_value; ///< "6"
    std::string pattern;       ///< "[Integer range 1...99 (inclusive)]"
  };

  /**
   * @brief A random value that satisfies the parameter's deal.II pattern
   * (Double/Integer ranges, Selection, Bool, List of Integer), read from its
   * description; the default for patterns it does not know. Values that
   * pass the patterns still meet the cross-parameter checks and the closed
   * forms' singular cases.
   */
  std::string
  in_range_value(RandomEngine &engine, const DeclaredParameter &parameter);

  /**
   * @brief Every parameter that Parameters::ScenarioParameters declares,
   * read back from deal.II's own JSON description so that parameters added
   * later are fuzzed without touching this code.
   */
  std::vector<DeclaredParameter>
  declared_parameters();

  /** How an input was made; reported per kind so a run shows its coverage. */
  enum class InputKind
  {
    default_scene,    ///< params/default.prm unchanged (+ maybe overrides)
    replaced_values,  ///< default.prm with a few values replaced
    every_parameter,  ///< every declared parameter written, many random
    byte_mutation,    ///< default.prm with random byte edits
    random_structure, ///< random subsection/set/end lines
    json_scene,       ///< .json scene, random values or broken syntax
    xml_scene         ///< .xml scene, random values or broken syntax
  };

  constexpr unsigned int n_input_kinds = 7;

  /** @brief "byte_mutation", ... for reports. */
  std::string
  to_string(const InputKind kind);

  /** One generated input: a scene file and command-line overrides. */
  struct SceneInput
  {
    InputKind                kind;
    std::string              extension; ///< ".prm", ".json" or ".xml"
    std::string              text;
    std::vector<std::string> overrides; ///< "Subsection/Entry=value"
  };

  /**
   * @brief Makes hostile scene inputs from a valid scene text and the
   * declared parameters. Deterministic for a given engine state.
   */
  class SceneTextGenerator
  {
  public:
    /** @param[in] valid_scene_text A scene that read_scenario accepts. */
    explicit SceneTextGenerator(const std::string &valid_scene_text);

    /** @brief The next input; kinds are drawn with fixed weights. */
    SceneInput
    next(RandomEngine &engine) const;

  private:
    std::string                    valid_text;
    std::vector<std::string>       valid_lines;
    std::vector<DeclaredParameter> parameters;

    std::string
    replaced_values(RandomEngine &engine) const;
    std::string
    every_parameter(RandomEngine &engine) const;
    std::string
    byte_mutation(RandomEngine &engine, const std::string &text) const;
    std::string
    random_structure(RandomEngine &engine) const;
    std::string
    json_scene(RandomEngine &engine) const;
    std::string
    xml_scene(RandomEngine &engine) const;
    std::vector<std::string>
    overrides(RandomEngine &engine) const;
    std::string
    value_for(RandomEngine &engine, const DeclaredParameter &parameter) const;
  };
} // namespace FloorBlock::Fuzz
