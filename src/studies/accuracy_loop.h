#pragma once

#include <output/fem_error_estimate.h>
#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>
#include <pipeline/fem_pipeline.h>

#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Studies
{
  /** The solve `run` reports, and the estimate of its error. */
  struct TargetedSolve
  {
    Pipeline::FemOutcome
      outcome; ///< the reported level (its files are in the folder)
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
  worst_target_error(const Output::FemErrorEstimate              &estimate,
                     const std::string                           &joint,
                     const std::vector<Parameters::TargetFigure> &figures);

  /**
   * @brief Accuracy as the input, the mesh as the output: solves the scene
   * on its Gmsh mesh (level 0, into @p folder) and on adaptive refinements
   * of it (AdaptiveLevels; level k into <folder>/refined/level_<k>/),
   * and checks a level by solving it again with every cell halved
   * (<folder>/refined/level_<k>_halved/), until a checked pair meets
   * Mesh/Target relative error for every Mesh/Target figures figure of the
   * face joint, or Mesh/Maximum refinement levels or Mesh/Refinement time
   * budget run out.
   *
   * One pair gives two estimates (refined_solve_error(), Roache's
   * grid-convergence index for each grid, plus the contact ends' location
   * uncertainty): the level's, 6 times the difference, and the check's,
   * 3 times. The level is reported when its estimate meets the target (it
   * is the cheaper solve -- the default scene meets 1 % on level 0 in
   * under 1 s), otherwise whichever of the two estimates is smaller, as a
   * rule the check's: the exact law on the default scene meets 1 % only
   * there. Where a check moves a figure opposite to the change from the
   * level before, both estimates are at least the range of the three
   * values (widen_where_oscillating(): a level and its check can agree by
   * chance). The reported solve's files (fem.json, joints.csv,
   * joint_profiles.csv, mesh.msh, deformed.png, vtu/) are copied into
   * @p folder. The estimate carries the loop's record
   * (Output::AccuracyTarget, with the reported level and solve) and says
   * when the target was not met and why.
   *
   * A pair that meets the target is confirmed by the next adaptive
   * level, which must lie inside every target figure's bracket; else the
   * estimate is widened to it and the loop refines on (TargetLoop,
   * widen_to_contain()). With Solver/FE degree = auto, degree 2's loop
   * joins when degree 1's level-0 pair misses, and the two take turns
   * until one meets the target (next_race_turn()); its solve is reported.
   *
   * With Solver/Error estimate = none: one solve, no estimate. The
   * rigid-block model (no mesh): one solve and one with twice the points
   * per joint (estimate_error()).
   */
  TargetedSolve
  solve_to_target(const Parameters::ScenarioParameters &scene,
                  const Output::ResultFolder           &folder);
} // namespace FloorBlock::Studies
