#pragma once

#include <parameters/uncertain_inputs.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace FloorBlock::Assessment
{
  /** How to build one case's scene: the scene file, its command-line
   * overrides, and the uncertain inputs a case sets. */
  struct SceneSource
  {
    std::string                             path;
    std::vector<std::string>                overrides;
    std::vector<Parameters::UncertainInput> inputs;
  };

  /** @brief What the FEM says of the floor for one draw of the inputs. */
  struct SafetyCase
  {
    std::string         id;     ///< "training_0007"
    std::vector<double> inputs; ///< as set, in each parameter's units
    /**
     * "solved"; "not converged" (the solve failed after its cutbacks);
     * "failed" (the mesher or a solver threw: message says what); or
     * "refused": the drawn scene is inadmissible (message says why).
     */
    std::string status;
    std::string message;
    /** The governing corner's factor by the verdict's method (-). */
    double       safety_factor = 0.;
    double       point_factor  = 0.;
    double       line_factor   = 0.;
    double       area_factor   = 0.;
    std::string  verdict_method;
    std::string  governing_corner;
    unsigned int n_dofs    = 0;
    double       wall_time = 0.; ///< s, of the whole case

    bool
    solved() const
    {
      return status == "solved";
    }
  };

  /**
   * @brief Reads the scene with the case's inputs set and solves it with
   * the contact FEM (no VTU, in a scratch folder): the governing corner's
   * safety factors at the end of the load path. A drawn scene the parser
   * refuses (e.g. a sampled block width too small for the critical
   * distance) or a solve that fails is a case with that status, not an
   * error of the study.
   */
  SafetyCase
  solve_safety_case(const SceneSource         &source,
                    const std::string         &id,
                    const std::vector<double> &values);

  /** @brief The overrides "Subsection/Entry=value" that set the inputs. */
  std::vector<std::string>
  input_overrides(const SceneSource &source, const std::vector<double> &values);

  nlohmann::json
  to_json(const SafetyCase &safety_case);

  /** @brief Throws std::runtime_error naming the key if @p json lacks one. */
  SafetyCase
  safety_case_from_json(const nlohmann::json &json);
} // namespace FloorBlock::Assessment
