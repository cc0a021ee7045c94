#pragma once

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /**
   * One FEM figure of a pair of solves, a coarse one and a refined one
   * (the same mesh with every cell halved), and the estimated error of
   * the one reported (FemErrorEstimate::reported_solve).
   */
  struct FigureError
  {
    double value         = 0.; ///< the reported solve's figure (SI unit)
    double refined_value = 0.; ///< the refined solve's figure
    /**
     * Estimated error of value: Studies::error_per_difference() times
     * |coarse_value - refined_value|, plus for a contact length the
     * reported solve's ends' location uncertainty.
     */
    double absolute_error = 0.;
    /** absolute_error / |refined_value|; none when refined_value is 0. */
    std::optional<double> relative_error;
    double                coarse_value = 0.; ///< the coarse solve's figure
    /**
     * The check moved the figure opposite to the previous level's change
     * (Studies::widen_where_oscillating()): absolute_error is then at
     * least the range of the three values.
     */
    bool oscillating = false;
    /**
     * The figure on the adaptive level after the reported one, when the
     * loop solved it to confirm the estimate
     * (Studies::widen_to_contain()); absolute_error is at least the
     * distance to it.
     */
    std::optional<double> next_level_value;
  };

  /** The estimated errors of one joint's figures. */
  struct JointErrors
  {
    FigureError normal_force;       ///< N/m
    FigureError contact_length;     ///< m
    FigureError sigma_max;          ///< Pa, pointwise peak normal stress
    FigureError sigma_max_averaged; ///< Pa, averaged over the averaging length
  };

  /**
   * The estimated errors of one floor-level corner's safety factors
   * (Safety::CornerSafety), where both solves resolve its path.
   */
  struct CornerErrors
  {
    FigureError point_factor; ///< -, the point method's FS
    FigureError line_factor;  ///< -, the line method's FS
    FigureError area_factor;  ///< -, the area method's FS
  };

  /** Which solve of a compared pair the figures are reported from. */
  enum class ReportedSolve
  {
    coarse, ///< the solve being checked (its error is 6 times the difference)
    refined ///< its check, every cell halved (3 times the difference)
  };

  /** summary.json's name of @p solve: "coarse" or "refined". */
  const char *
  reported_solve_name(ReportedSolve solve);

  /** One mesh of `run`'s accuracy loop (Studies::solve_to_target()). */
  struct RefinementLevelRecord
  {
    unsigned int level     = 0;
    unsigned int n_cells   = 0;
    unsigned int n_dofs    = 0;
    double       wall_time = 0.; ///< s: meshing or refinement, and the solve
    std::string  status;         ///< fem.json's status of the level's solve
    /** The face joint's figures on this level, by fem.json key (SI). */
    std::map<std::string, double> face_figures;
    /**
     * Largest relative difference-based indicator of the target figures:
     * Studies::error_from_refined_difference times the change from the
     * previous level; none on level 0. It only decides whether the level
     * is checked.
     */
    std::optional<double> difference_indicator;
    /** DoFs of the check (the level's mesh, every cell halved); 0: none. */
    unsigned int halved_n_dofs    = 0;
    double       halved_wall_time = 0.; ///< s, the check's mesh and solve
    /**
     * Largest estimated relative error of the level's target figures from
     * the check; none if the level was not checked.
     */
    std::optional<double> worst_target_error;
    /**
     * The same for the check's own figures (the refined solve of the
     * pair); none if the level was not checked.
     */
    std::optional<double> halved_worst_target_error;
  };

  /** What `run` was asked to reach, and how far it got. */
  struct AccuracyTarget
  {
    double relative_error = 0.;       ///< Mesh/Target relative error
    std::vector<std::string> figures; ///< fem.json keys of the target figures
    bool                     met = false;
    unsigned int reported_level  = 0; ///< the level the figures come from
    /** The level itself or its check (the level's mesh, every cell halved). */
    ReportedSolve reported_solve = ReportedSolve::coarse;
    std::string   stop_reason;   ///< why the loop stopped, in words
    unsigned int  fe_degree = 1; ///< FE degree of the loop's solves
    /**
     * The adaptive level solved after a checked pair met the target, to
     * confirm it (Studies::widen_to_contain()); none if no pair met.
     */
    std::optional<unsigned int> confirming_level;
    /** How the FE degree was chosen (Solver/FE degree), in words. */
    std::string fe_degree_choice;
    /**
     * The other FE degree's loop when Solver/FE degree = auto raced both
     * (Studies::next_race_turn()): its levels and why it stopped.
     */
    std::vector<AccuracyTarget>        other_degrees;
    double                             wall_time = 0.; ///< s, all levels
    std::vector<RefinementLevelRecord> levels;
  };

  /**
   * The discretisation error of each FEM figure, estimated from the
   * difference to one refined solve (summary.json's fem_error_estimate).
   */
  struct FemErrorEstimate
  {
    std::string method;            ///< how the refined solve was refined
    bool        available = false; ///< false: the refined solve failed
    /** Which of the two solves FigureError::value is from. */
    ReportedSolve reported_solve = ReportedSolve::coarse;
    std::string   status_text; ///< why not available (else empty)
    unsigned int  refined_n_dofs = 0;
    std::string   refined_status;
    /** By joint name ("vertical 6"), as in fem.json. */
    std::map<std::string, JointErrors> joints;
    /** By corner (Safety::CornerPath::label(), "face block at vertical 6"). */
    std::map<std::string, CornerErrors> corners;
    /** The accuracy loop that chose the levels compared; none without one. */
    std::optional<AccuracyTarget> target;
  };

  /**
   * @brief summary.json's fem_error_estimate: method and status; when
   * available the reported solve ("coarse" or "refined"), the refined
   * DoFs and status and, per joint and figure (keys of fem.json:
   * normal_force_N_per_m, contact_length_m, sigma_max_Pa,
   * sigma_max_averaged_Pa), value, coarse_value, refined_value,
   * absolute_error, relative_error (null where the refined value is 0)
   * oscillating and next_level_value (null unless a confirming level was
   * solved); with an accuracy loop its "target": relative_error,
   * figures, met, reported_level, reported_solve ("coarse": the level,
   * "refined": its check), stop_reason, fe_degree, confirming_level,
   * fe_degree_choice, other_fe_degrees (the same record, per degree),
   * wall_time_s and per level level, n_cells, n_dofs,
   * wall_time_s, status, face (figures by fem.json key),
   * difference_indicator, halved_n_dofs, worst_target_relative_error and
   * halved_worst_target_relative_error (null where not estimated); per
   * corner whose path both solves resolve, "corners": safety_factor_point
   * and safety_factor_line with the same entries as a joint's figures.
   */
  nlohmann::json
  fem_error_estimate_json(const FemErrorEstimate &estimate);
} // namespace FloorBlock::Output
