#pragma once

#include <parameters/sections.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace FloorBlock::Parameters
{
  /**
   * @brief Every subsection of a scene file, parsed into SI values.
   *
   * Aggregated as members (not by inheritance) so each subsection stays an
   * independent, testable value.
   */
  struct ScenarioParameters
  {
    GeometryParameters    geometry;
    BeddingParameters     bedding;
    MaterialParameters    material;
    StrengthParameters    strength;
    JointParameters       joints;
    LoadingParameters     loading;
    MeshParameters        mesh;
    SolverParameters      solver;
    VerifyParameters      verify;
    ModelParameters       model;
    CornerParameters      corner;
    UncertaintyParameters uncertainty;

    /// Name of the scene: the file's stem ("default" for params/default.prm).
    std::string scene_name;
    /// The input exactly as read, echoed into results/ as original.prm.
    std::string original_text;
    /// Every parameter after overrides, echoed into results/ as parameters.prm.
    std::string expanded_text;
    /// Inputs that are accepted but mean something the user may not expect
    /// (a floor lift the closed forms do not share); each command prints
    /// them and report.md lists them.
    std::vector<std::string> warnings;

    /** Declares every subsection's entries. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Reads every subsection and runs the checks that span subsections. */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief The block numbers (chapter numbering: 1 = free end, n = next to
     * the face block) of the loaded blocks.
     */
    std::vector<unsigned int>
    loaded_blocks() const;

    /**
     * @brief Whether the FEM's uplift bends its flat bed into the bedding
     * the closed forms stand the blocks on: Bedding/Floor uplift reading =
     * lifted with Loading/Uplift mode = parabola on a parabolic bedding or
     * slope on a planar one.
     */
    bool
    uplift_follows_bedding() const;
  };

  /**
   * @brief Whether a floor lift @p lift (m) bends a flat bed into a bedding
   * that rises by @p rise (m) at the free end: within 1 % of the rise, which
   * puts the FEM's floor on the closed forms' to less than the chapter's
   * quoted digits.
   */
  bool
  lift_matches_rise(double lift, double rise);

  /**
   * @brief Reads a scene file (.prm or .json) and applies command-line
   * overrides of the form "Subsection/Entry name=value".
   *
   * @throws InputError naming the file and line where known, the parameter,
   * the value and what is allowed: for a missing or unreadable file, an
   * unknown name, a value outside its pattern, or an impossible scene.
   */
  ScenarioParameters
  read_scenario(const std::string              &path,
                const std::vector<std::string> &overrides);

  /**
   * @brief The declared defaults with @p overrides applied, for commands
   * that take no scene file (verification cases).
   */
  ScenarioParameters
  read_defaults(const std::string              &name,
                const std::vector<std::string> &overrides);

  /** @brief Every parameter with default, pattern, units and meaning. */
  std::string
  describe_all_parameters();
} // namespace FloorBlock::Parameters
