#pragma once

#include <output/fem_error_estimate.h>
#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>
#include <pipeline/fem_pipeline.h>

#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Pipeline
{
  /** The solve `run` reports, and the estimate of its error. */
  struct TargetedSolve
  {
    FemOutcome outcome; ///< the reported level (its files are in the folder)
    std::optional<Output::FemErrorEstimate> estimate;
  };

  /**
   * @brief fem.json's key of a Mesh/Target figures entry
   * ("contact_length_m", ...), as in the error estimate.
   */
  std::string
  target_figure_key(Parameters::TargetFigure figure);

  /**
   * @brief The largest estimated relative error among @p figures of joint
   * @p joint in @p estimate; none if the estimate is not available or
   * lacks the joint. A figure whose relative error is undefined (refined
   * value 0) counts as 0 if its absolute error is 0 (both levels say
   * "nothing") and as unbounded otherwise.
   */
  std::optional<double>
  worst_target_error(const Output::FemErrorEstimate                &estimate,
                     const std::string                             &joint,
                     const std::vector<Parameters::TargetFigure>   &figures);

  /**
   * @brief Accuracy as the input, the mesh as the output: solves the scene
   * on its Gmsh mesh (level 0, into @p folder) and on adaptive refinements
   * of it (AdaptiveLevels; level k into <folder>/refined/level_<k>/),
   * until the estimate of level k from level k + 1
   * (refined_solve_error(): 6 times the difference, plus a contact end's
   * location uncertainty) is within Mesh/Target relative error for every
   * Mesh/Target figures figure of the face joint, or Mesh/Maximum
   * refinement levels or Mesh/Refinement time budget run out.
   *
   * Level k is reported, not k + 1: the estimate is the error of the
   * coarser of the two solves (Richardson/Roache on two grids), and it is
   * the cheaper one -- the default scene meets 1 % on level 0. The
   * reported level's files (fem.json, joints.csv, joint_profiles.csv,
   * mesh.msh, deformed.png, vtu/) are copied into @p folder. The estimate
   * carries the loop's record (Output::AccuracyTarget) and says when the
   * target was not met and why.
   *
   * With Solver/Error estimate = none: one solve, no estimate. The
   * rigid-block model (no mesh): one solve and one with twice the points
   * per joint (estimate_error()).
   */
  TargetedSolve
  solve_to_target(const Parameters::ScenarioParameters &scene,
                  const Output::ResultFolder           &folder);
} // namespace FloorBlock::Pipeline
