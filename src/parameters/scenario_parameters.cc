#include <common/input_error.h>
#include <parameters/parameter_error_text.h>
#include <parameters/scenario_parameters.h>
#include <parameters/scene_file_checks.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace FloorBlock::Parameters
{
  using dealii::ParameterHandler;

  void
  ScenarioParameters::declare_parameters(ParameterHandler &prm)
  {
    GeometryParameters::declare_parameters(prm);
    BeddingParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    StrengthParameters::declare_parameters(prm);
    JointParameters::declare_parameters(prm);
    LoadingParameters::declare_parameters(prm);
    MeshParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
    VerifyParameters::declare_parameters(prm);
    ModelParameters::declare_parameters(prm);
    CornerParameters::declare_parameters(prm);
    UncertaintyParameters::declare_parameters(prm);
  }

  namespace
  {
    /**
     * The support footprint (Loading/Footprint length, offset) lies on the
     * face of a 3D scene: a footprint along the face has no meaning in the
     * plane-strain 2D model, whose load is per metre of face.
     */
    void
    check_footprint(const GeometryParameters &geometry,
                    const LoadingParameters  &loading)
    {
      const double length = loading.footprint_length;
      if (length > 0. && geometry.dimension != 3)
        throw InputError("Loading/Footprint length",
                         std::to_string(length),
                         "must be 0 while Geometry/Dimension = 2: a "
                         "footprint along the face needs a 3D scene");
      if (length > geometry.face_length)
        throw InputError("Loading/Footprint length",
                         std::to_string(length),
                         "must be between 0 and Geometry/Face length = " +
                           std::to_string(geometry.face_length) + " m");
      if (!loading.footprint_offset)
        return;
      const double offset = *loading.footprint_offset;
      if (!(length > 0.))
        throw InputError("Loading/Footprint offset",
                         std::to_string(offset),
                         "must be -1 (the default) while Loading/Footprint "
                         "length = 0: there is no footprint to place");
      // Round-off of an offset written as Face length - Footprint length.
      const double slack = 1e-9 * geometry.face_length;
      if (offset + length > geometry.face_length + slack)
        throw InputError("Loading/Footprint offset",
                         std::to_string(offset),
                         "must be -1 (centred) or between 0 and Geometry/Face "
                         "length - Loading/Footprint length = " +
                           std::to_string(geometry.face_length - length) +
                           " m");
    }

    bool
    uplift_follows_bedding(const BeddingParameters &bedding,
                           const UpliftMode         mode)
    {
      return bedding.floor_uplift ==
               Geometry::FloorUplift::lifted_flat_bedding &&
             (bedding.shape == Geometry::BeddingShape::parabolic ?
                mode == UpliftMode::parabola :
                mode == UpliftMode::slope);
    }

    std::string
    number_text(const double value)
    {
      std::ostringstream text;
      text.precision(6);
      text << value;
      return text.str();
    }

    std::string
    metres(const double value)
    {
      return number_text(value) + " m";
    }

    /**
     * The closed forms stand the blocks on the bedding; the FEM starts from
     * a flat bed (reading lifted) and bends it into that bedding only when
     * its uplift follows the same profile and reaches the bedding's rise at
     * the free end. Elsewhere the FEM's lift is a motion the closed forms
     * do not describe.
     */
    void
    resolve_floor_lift(const GeometryParameters &geometry,
                       const BeddingParameters  &bedding,
                       LoadingParameters        &loading,
                       std::vector<std::string> &warnings)
    {
      const bool parabolic = bedding.shape == Geometry::BeddingShape::parabolic;
      const bool follows_bedding =
        uplift_follows_bedding(bedding, loading.uplift_mode);
      const double rise =
        bedding.rise_at_free_end(geometry.n_blocks, geometry.block_width);
      const std::string rise_text =
        (parabolic ?
           "(nL)^2/k = (" + std::to_string(geometry.n_blocks) + " x " +
             metres(geometry.block_width) + ")^2 / " +
             metres(bedding.curvature) :
           "nL tan(alpha) = " + std::to_string(geometry.n_blocks) + " x " +
             metres(geometry.block_width) + " x tan(" +
             number_text(bedding.inclination * 180. / M_PI) + " deg)") +
        " = " + metres(rise);
      const std::string how_to_fix =
        parabolic ? "Bedding/Curvature, Geometry/Number of blocks or Block "
                    "width" :
                    "Bedding/Inclination, Geometry/Number of blocks or Block "
                    "width";

      if (loading.floor_lift_auto)
        {
          if (follows_bedding && rise < 0.)
            throw InputError("Loading/Floor lift",
                             "auto",
                             "needs a bedding that rises away from the face: "
                             "the bedding's " +
                               rise_text +
                               "; set Bedding/Inclination >= 0 or give the "
                               "lift in m (>= 0)");
          loading.floor_lift        = std::max(rise, 0.);
          loading.floor_lift_origin = "auto: " + rise_text;
          if (!follows_bedding)
            warnings.push_back(
              "Loading/Floor lift = auto takes the bedding's " + rise_text +
              ", but the closed forms define no FEM lift for this scene "
              "(Bedding/Floor uplift reading and Loading/Uplift mode do not "
              "bend a flat bed into the " +
              (parabolic ? "parabolic" : "planar") +
              " bedding): give Loading/Floor lift in m to choose the "
              "motion");
          return;
        }

      const double lift        = loading.floor_lift;
      const bool   contradicts = !lift_matches_rise(lift, rise);
      // A level bed moved up or along itself keeps the closed forms' bed:
      // the motion only drives the slip they describe.
      const bool moves_level_bed =
        rise == 0. && loading.uplift_mode != UpliftMode::tilt;
      if (!follows_bedding && moves_level_bed)
        return;
      if (!follows_bedding)
        {
          warnings.push_back(
            "Loading/Floor lift = " + metres(lift) +
            " moves the FEM's base in a way the closed forms do not "
            "describe (Bedding/Floor uplift reading and Loading/Uplift mode "
            "do not bend a flat bed into the bedding); the closed forms "
            "stand the blocks on the bedding as it is, whose " +
            rise_text);
          return;
        }
      if (!contradicts)
        return;
      if (!loading.floor_lift_may_differ)
        throw InputError(
          "Loading/Floor lift",
          metres(lift),
          "must equal the bedding's " + rise_text +
            " within 1 %: the closed forms stand the blocks on that "
            "bedding. Set Loading/Floor lift = auto, change " +
            how_to_fix +
            ", or set Loading/Floor lift against bedding = may differ to "
            "lift the FEM's floor by another amount");
      warnings.push_back("Loading/Floor lift = " + metres(lift) +
                         " differs from the bedding's " + rise_text +
                         " (Floor lift against bedding = may differ): the "
                         "FEM lifts another floor than the closed forms "
                         "stand the blocks on");
    }

    /**
     * Appends "# <note>" to the line "set <entry> = ..." of subsection
     * @p subsection in a ShortPRM text, so parameters.prm stays readable
     * as input and still shows a derived value.
     */
    std::string
    annotate_entry(const std::string &text,
                   const std::string &subsection,
                   const std::string &entry,
                   const std::string &note)
    {
      std::istringstream lines(text);
      std::string        line, annotated, current;
      const std::string  opening = "subsection ";
      while (std::getline(lines, line))
        {
          const std::string trimmed = dealii::Utilities::trim(line);
          if (trimmed.rfind(opening, 0) == 0)
            current = dealii::Utilities::trim(trimmed.substr(opening.size()));
          const std::string set = "set " + entry;
          if (current == subsection && trimmed.rfind(set, 0) == 0 &&
              dealii::Utilities::trim(trimmed.substr(set.size()))
                  .rfind("=", 0) == 0)
            line += " # " + note;
          annotated += line + "\n";
        }
      return annotated;
    }
  } // namespace

  void
  ScenarioParameters::parse_parameters(ParameterHandler &prm)
  {
    geometry.parse_parameters(prm);
    bedding.parse_parameters(prm);
    material.parse_parameters(prm);
    strength.parse_parameters(prm);
    joints.parse_parameters(prm);
    loading.parse_parameters(prm);
    mesh.parse_parameters(prm);
    solver.parse_parameters(prm);
    verify.parse_parameters(prm);
    model.parse_parameters(prm);
    corner.parse_parameters(prm, geometry.n_blocks);
    uncertainty.parse_parameters(prm);
    // Here, so that every command solves with the same joints.
    joints.resolve_stiffness(geometry, strength);

    // Fillet pairs start with a gap; the joint law treats a pair as closed
    // while kn * gap stays below the tensile strength, so any tensile
    // strength would glue facing fillets together across their gap.
    if (geometry.corner_rounding_radius > 0 && joints.tensile_strength > 0)
      throw InputError("Joints/Tensile strength",
                       std::to_string(joints.tensile_strength),
                       "must be 0 while Geometry/Corner rounding radius > 0 "
                       "(rounded corners start with an open gap)");

    // The rigid half-plane is the plane y = 0 of the mesh.
    if (bedding.rigid_base && !bedding.flat_in_mesh())
      throw InputError("Bedding/Base",
                       "rigid",
                       "needs a flat bedding in the mesh: Bedding/Floor "
                       "uplift reading = lifted, or Shape = planar with "
                       "Inclination = 0");

    for (const unsigned int from_face : loading.loaded_blocks_from_face)
      if (from_face > geometry.n_blocks)
        throw InputError("Loading/Loaded blocks from face",
                         std::to_string(from_face),
                         "each loaded block must be between 1 and "
                         "Geometry/Number of blocks = " +
                           std::to_string(geometry.n_blocks));

    check_footprint(geometry, loading);

    warnings.clear();
    resolve_floor_lift(geometry, bedding, loading, warnings);

    model.choose(bedding, joints, loading);

    // A 2D elastic solve reads the stress within L of every top corner of
    // every block (src/safety/): the quarter disc of radius L from the
    // corner's surface point must lie in its block.
    if (model.chosen == BlockModel::elastic && geometry.dimension == 2)
      {
        const double smallest_side = std::min({geometry.block_width,
                                               geometry.block_height,
                                               geometry.face_block_width});
        const double room = smallest_side - geometry.corner_rounding_radius;
        if (!(strength.critical_distance < room))
          throw InputError(
            "Strength/Critical distance",
            std::to_string(strength.critical_distance) + " m",
            "must be below the smallest block side less the corner "
            "rounding radius, " +
              std::to_string(room) +
              " m: the floor's safety factor reads the stress within L of "
              "each block's top corners, inside the block (set it, or "
              "Strength/Fracture toughness and Tensile strength for auto)");
      }

    // The elastic FEM pairs the nodes of both joint sides one to one
    // (src/contact/README.md). Refused here, non-matching sides stop before
    // meshing with this entry's name instead of after it with a message
    // about a node and files already written.
    if (!mesh.matching_joints && model.chosen == BlockModel::elastic)
      throw InputError("Mesh/Matching joints",
                       "false",
                       "must be true while the elastic FEM is the model "
                       "(" +
                         model.choice_reason +
                         "): its joints pair the "
                         "nodes of both sides one to one");
  }

  std::vector<unsigned int>
  ScenarioParameters::loaded_blocks() const
  {
    // Counted from the face: 1 is block n, n is block 1.
    std::vector<unsigned int> blocks;
    for (const unsigned int from_face : loading.loaded_blocks_from_face)
      blocks.push_back(geometry.n_blocks + 1 - from_face);
    return blocks;
  }

  bool
  lift_matches_rise(const double lift, const double rise)
  {
    return std::abs(lift - rise) <= 0.01 * std::abs(rise);
  }

  bool
  ScenarioParameters::uplift_follows_bedding() const
  {
    return Parameters::uplift_follows_bedding(bedding, loading.uplift_mode);
  }

  namespace
  {
    std::string
    read_text(const std::string &path)
    {
      if (!std::filesystem::is_regular_file(path))
        throw InputError("scene file '" + path +
                         "' does not exist or is not a regular file");
      std::ifstream     in(path);
      std::stringstream text;
      text << in.rdbuf();
      if (!in)
        throw InputError("scene file '" + path + "' cannot be read");
      return text.str();
    }

    /** Every entry a scene file may set. */
    std::vector<std::string>
    declared_entry_paths()
    {
      ParameterHandler prm;
      ScenarioParameters::declare_parameters(prm);
      return entry_paths(prm);
    }

    /** parameter_error_text() and, where it helps, what to do about it. */
    std::string
    explained(const dealii::ExceptionBase &error,
              const std::string           &parameter_path,
              const std::string           &value,
              const std::string           &file_text)
    {
      const std::string text =
        parameter_error_text(error, parameter_path, value);
      return text + parse_error_hint(text, file_text, declared_entry_paths());
    }

    /// Splits "Joints/Bedding friction angle=20" into path and value and sets
    /// it.
    void
    apply_override(ParameterHandler &prm, const std::string &assignment)
    {
      const auto equals = assignment.find('=');
      const auto slash  = assignment.rfind('/', equals);
      if (equals == std::string::npos || slash == std::string::npos)
        throw InputError("--set '" + assignment +
                         "': expected \"Subsection/Entry name=value\"");

      const std::string path =
        dealii::Utilities::trim(assignment.substr(0, equals));
      const std::string value =
        dealii::Utilities::trim(assignment.substr(equals + 1));
      const std::vector<std::string> levels =
        dealii::Utilities::split_string_list(path, '/');

      for (unsigned int level = 0; level + 1 < levels.size(); ++level)
        prm.enter_subsection(levels[level]);
      try
        {
          prm.set(levels.back(), value);
        }
      catch (const dealii::ExceptionBase &error)
        {
          throw InputError("--set '" + assignment +
                           "': " + explained(error, path, value, ""));
        }
      for (unsigned int level = 0; level + 1 < levels.size(); ++level)
        prm.leave_subsection();
    }
  } // namespace

  namespace
  {
    /** The expanded parameters with the values derived from others. */
    std::string
    expanded_with_notes(const ScenarioParameters &scenario,
                        const std::string        &expanded)
    {
      std::string text = expanded;
      for (const auto &[entry, note] : scenario.material.derived_text)
        text = annotate_entry(text, "Material", entry, note);
      if (!scenario.joints.stiffness_origin.empty())
        {
          text = annotate_entry(text,
                                "Joints",
                                "Stiffness source",
                                scenario.joints.stiffness_origin);
          for (const char *entry : {"Normal stiffness", "Shear stiffness"})
            text = annotate_entry(text,
                                  "Joints",
                                  entry,
                                  "unused: Stiffness source = Barton-Bandis");
        }
      if (!scenario.loading.floor_lift_origin.empty())
        text = annotate_entry(text,
                              "Loading",
                              "Floor lift",
                              scenario.loading.floor_lift_origin);
      return text;
    }
  } // namespace

  ScenarioParameters
  read_scenario(const std::string              &path,
                const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    ScenarioParameters::declare_parameters(prm);

    ScenarioParameters scenario;
    scenario.original_text = read_text(path);
    scenario.scene_name    = std::filesystem::path(path).stem().string();
    check_scene_file_text(path, scenario.original_text);

    try
      {
        // Files name their format by extension (.prm, .json, .xml).
        prm.parse_input(path, "", false, true);
      }
    catch (const dealii::ExceptionBase &error)
      {
        throw InputError(path + ": " +
                         explained(error, "", "", scenario.original_text));
      }
    catch (const boost::property_tree::ptree_error &error)
      {
        // deal.II lets Boost's XML syntax errors through unwrapped.
        throw InputError(path + ": " + error.what());
      }

    for (const std::string &assignment : overrides)
      apply_override(prm, assignment);

    try
      {
        scenario.parse_parameters(prm);
      }
    catch (const dealii::ExceptionBase &error)
      {
        // A value can pass its pattern and still fail get_double(), e.g.
        // "1e-400": the pattern's stream read underflows to 0 silently,
        // deal.II's strtod conversion reports ERANGE and throws.
        throw InputError(path + ": " + parameter_error_text(error, "", ""));
      }

    std::ostringstream expanded;
    prm.print_parameters(expanded, ParameterHandler::ShortPRM);
    scenario.expanded_text = expanded_with_notes(scenario, expanded.str());
    return scenario;
  }

  ScenarioParameters
  read_defaults(const std::string              &name,
                const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    ScenarioParameters::declare_parameters(prm);
    for (const std::string &assignment : overrides)
      apply_override(prm, assignment);

    ScenarioParameters scenario;
    scenario.scene_name = name;
    scenario.parse_parameters(prm);
    std::ostringstream expanded;
    prm.print_parameters(expanded, ParameterHandler::ShortPRM);
    scenario.expanded_text = expanded_with_notes(scenario, expanded.str());
    scenario.original_text = expanded.str();
    return scenario;
  }

  std::string
  describe_all_parameters()
  {
    ParameterHandler prm;
    ScenarioParameters::declare_parameters(prm);
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::PRM);
    return text.str();
  }
} // namespace FloorBlock::Parameters
