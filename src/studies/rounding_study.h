#pragma once

#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>

#include <studies/corner_analysis.h>

#include <functional>
#include <vector>

namespace FloorBlock::Studies
{
  /** @brief The corner's peak at one rounding radius. */
  struct RoundingPoint
  {
    double radius         = 0.; ///< m
    double peak           = 0.; ///< Pa, pointwise peak of the last level
    double averaged_peak  = 0.; ///< Pa, over the scene's averaging length
    double contact_length = 0.; ///< m, the joint's closed length
    double edge_beyond_corner =
      0.; ///< m, how far the contact reaches into the fillet
    /** Relative peak change over the last two levels: the convergence reached.
     */
    double last_change = 0.;
    /** Last two changes within Corner/Converged change, the fillet's contact
     * resolved. */
    bool         converged     = false;
    unsigned int n_levels      = 0;
    unsigned int n_dofs        = 0;
    double       smallest_size = 0.; ///< m, cells asked for on the last level
    double       wall_time     = 0.; ///< s, all levels
  };

  /** @brief The rounding study and the power law fitted through it. */
  struct RoundingStudy
  {
    std::vector<RoundingPoint> points;
    /** Slope of log peak against log radius (least squares), all converged
     * points. */
    double fitted_power = 0.;
    /** Whether every converged point's peak is below the one at the next
     * smaller radius. */
    bool falls_with_radius = false;
  };

  /**
   * @brief Solves @p scene once per Corner/Rounding radii entry, with the
   * scene's own global refinements (the far field fixed), and zooms
   * on its corner until the peak changed by at most Corner/Converged
   * change twice in a row (CornerZoom); a radius equal to the scene's own
   * takes the points of @p own (its analysis is not repeated).
   * Radii not started for lack of time are left out.
   */
  RoundingStudy
  rounding_study(const Parameters::ScenarioParameters &scene,
                 const CornerAnalysis                 &own,
                 const Output::ResultFolder           &folder,
                 const std::function<double()>        &seconds_left,
                 const Progress                       &progress);

  /**
   * Cells the zoom must put over the contact's reach into the fillet
   * before a peak may count as converged: two small changes in a row on
   * a coarse fillet contact can be a pause, not the limit (measured at
   * 1 cm: 315, 309, 307.6 MPa with 4 to 20 um cells, 305.8 MPa at 0.3 um).
   */
  constexpr double smallest_cells_in_fillet_contact = 100.;

  /**
   * @brief A rounding point from an analysis' levels: converged when the
   * peak changed by at most @p tolerance twice in a row and the last
   * level's cells are at most 1/100 of the contact's reach into the fillet.
   */
  RoundingPoint
  rounding_point(double                        radius,
                 const std::vector<ZoomLevel> &levels,
                 double                        tolerance);
} // namespace FloorBlock::Studies
