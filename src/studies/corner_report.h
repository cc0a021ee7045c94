#pragma once

#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>

#include <nlohmann/json.hpp>
#include <studies/corner_analysis.h>
#include <studies/rounding_study.h>

#include <string>

namespace FloorBlock::Studies
{
  /**
   * @brief corner.json: the corner's site, state and theory, the fits of
   * the last level with their range, K1 per level, every level's figures,
   * Eq. 6.53 against the field (matching_averaging_length_m null where no
   * length makes the field's mean equal it), and the rounding study (list
   * rounding_study of objects with radius_m and sigma_max_Pa).
   * Units in the keys.
   */
  nlohmann::json
  corner_json(const Parameters::ScenarioParameters &scene,
              const CornerAnalysis                 &analysis,
              const RoundingStudy                  &rounding);

  /**
   * @brief corner_traction.csv (last level: distance from the contact's
   * end, traction, whether fitted, the two-term fit and its leading term),
   * corner_levels.csv, rounding_study.csv, and the log-log plots
   * corner_traction.png and rounding_study.png (gnuplot).
   */
  void
  write_corner_tables_and_plots(const Output::ResultFolder &folder,
                                const CornerAnalysis       &analysis,
                                const RoundingStudy        &rounding);

  /**
   * @brief The files of `floorblock corner`: corner.json (corner_json()
   * with the command's @p wall_time in s), the tables and plots of
   * write_corner_tables_and_plots(), and last summary.json, whose presence
   * marks a finished command.
   */
  void
  write_corner_report(const Output::ResultFolder           &folder,
                      const Parameters::ScenarioParameters &scene,
                      const CornerAnalysis                 &analysis,
                      const RoundingStudy                  &rounding,
                      double                                wall_time);

  /** @brief The lines `corner` prints at the end. */
  std::string
  corner_summary_lines(const CornerAnalysis &analysis,
                       const RoundingStudy  &rounding);

  /**
   * @brief Exponent of the sharp corner's lowest mode for the state of
   * @p analysis' last level: the outer field that the nested asymptotics
   * of a small rounding radius r see.
   */
  double
  sharp_corner_exponent(const CornerAnalysis &analysis);

  /**
   * @brief The power of the peak against the rounding radius that the
   * nested asymptotics predict (M. Ciavarella, D. A. Hills, G. Monno,
   * Proc. IMechE C 212, 1998, for a punch with rounded edges): a singular
   * sharp corner, t ~ K r^(lambda - 1) with lambda < 1, caps at a peak
   * ~ K rho^(lambda - 1); a sharp corner without a singular mode
   * (lambda >= 1) leaves the peak independent of rho at leading order: 0.
   */
  double
  predicted_rounding_power(double sharp_exponent);
} // namespace FloorBlock::Studies
