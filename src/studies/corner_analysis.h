#pragma once

#include <corner/corner_fit.h>
#include <corner/corner_theory.h>
#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>

#include <studies/corner_zoom.h>

#include <functional>
#include <string>
#include <vector>

namespace FloorBlock::Studies
{
  /** @brief One level's figures as the analysis compares them. */
  struct LevelFigures
  {
    /** K1, K2 over the final fit range, exponents the theory's. */
    Corner::Intensities intensity;
    /** Relative change of the peak and of K1 from the level before. */
    double peak_change      = 0.;
    double intensity_change = 0.;
    /** The fitted exponent (Corner::fit_corner's expansion) on this level; 0
     * without a range. */
    double exponent = 0.;
  };

  /** @brief Everything `floorblock corner` finds at one corner. */
  struct CornerAnalysis
  {
    Corner::CornerSite        site;
    Corner::CornerMaterials   materials;
    std::vector<ZoomLevel>    levels;
    std::vector<LevelFigures> figures; ///< one per level
    Corner::CornerTheory      theory;  ///< for the last level's state
    Corner::CornerFit         fit;     ///< of the last level's traction
    /** The mean pressure's fit range and fit (Corner::fit_invariant), last
     * level. */
    Corner::DistanceRange   invariant_range;
    Analytic::AsymptoticFit invariant_fit;
    /** Whether the peak and K1 met Corner/Converged change. */
    bool        converged = false;
    std::string stop_reason;
    /** Eq. 6.53's sigma_max with the last level's Q and rotation (Pa). */
    double closed_form_peak = 0.;
    /**
     * Length over which the traction nearest the corner, averaged from
     * the contact's end, equals closed_form_peak (m); 0 if no length does.
     */
    double matching_averaging_length = 0.;
  };

  /** Progress lines (one per level). */
  using Progress = std::function<void(const std::string &)>;

  /**
   * @brief Zooms on @p scene's Corner/Joint floor-level corner until the
   * pointwise peak (twice in a row) and the leading intensity K1 (where
   * the theory covers the state, over a fit range of at least a decade)
   * change by at most Corner/Converged change between levels and the
   * fitted exponent by at most converged_exponent_change, or the levels or
   * @p deadline (s of @p clock_start's timer) run out; then fits the last
   * level's traction near the contact's end (Corner::fit_corner) over the
   * distances where it agrees with the level before within Corner/
   * Converged change, from 8 node spacings at the end to half the
   * distance of the peak (the zone's own length scale). Level files go to
   * @p folder/level_<k>.
   */
  CornerAnalysis
  analyse_corner(const Parameters::ScenarioParameters &scene,
                 const Output::ResultFolder           &folder,
                 const std::function<double()>        &seconds_left,
                 const Progress                       &progress);

  /** Smallest distance fitted, in node spacings at the contact's end. */
  constexpr double fit_from_spacings = 8.;
  /** Largest distance fitted, as a fraction of the peak's distance from the
   * end. */
  constexpr double fit_to_peak_fraction = 0.5;
  /**
   * Largest distance of the mean pressure's fit, as a fraction of the
   * peak's distance from the end: the mean pressure carries the stress
   * along the joint as well, which the peak's neighbourhood bends sooner
   * than the normal traction (measured on the 3-block scene with 5 cm
   * fillets: the four-term fit gives 1.53 up to a quarter, 1.005 -- the
   * scan's lower end -- up to half).
   */
  constexpr double invariant_to_peak_fraction = 0.25;

  /**
   * Largest change of the fitted exponent between the last two levels at
   * which the zoom may stop: K1 can settle within 2 % while the exponent
   * still drifts (default scene, exact law: 1.445 on the level where K1
   * first changed by 1.5 %, 1.48 three levels later).
   */
  constexpr double converged_exponent_change = 0.01;

  /**
   * Smallest ratio of the fit range's ends at which the zoom may stop: an
   * exponent needs a decade of distance.
   */
  constexpr double smallest_fit_span = 10.;
} // namespace FloorBlock::Studies
