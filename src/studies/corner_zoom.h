#pragma once

#include <corner/corner_profile.h>
#include <corner/corner_site.h>
#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>

#include <studies/adaptive_levels.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Studies
{
  /** @brief One level of a zoom on a corner. */
  struct ZoomLevel
  {
    unsigned int level  = 0;
    unsigned int n_dofs = 0;
    /** Cell size asked for in the zoom window (m); level 0: the scene's corner
     * size. */
    double                requested_size = 0.;
    double                wall_time      = 0.; ///< s, mesh and solve
    Corner::CornerProfile profile;
    /** The joint's figures (Contact::JointReport without its profile). */
    double normal_force         = 0.; ///< N/m
    double closed_length        = 0.; ///< m
    double peak_normal_stress   = 0.; ///< Pa, pointwise
    double averaged_peak_stress = 0.; ///< Pa, over the scene's averaging length
    double averaging_length     = 0.; ///< m
    /** The joint's relative rotation (rad) and Eq. 6.51/6.53's contact
     *  length (m) and sigma_max (Pa) with this level's Q and rotation
     *  (Compare::compare_vertical_joints). */
    /**
     * Mean pressure (Pa, compression > 0) of the cells along the joint
     * side the profile lists (Corner::mean_pressure_on_side, at the cell
     * centres) against the distance of their face's midpoint from the contact's
     * end, nearest first.
     */
    std::vector<Analytic::RadialSample> invariant_samples;
    double                              relative_rotation          = 0.;
    double                              closed_form_contact_length = 0.;
    double                              closed_form_peak           = 0.;
  };

  /**
   * @brief Relative change of the peak traction from level @p k - 1 to
   * level @p k of @p levels (1 where the earlier peak is zero).
   */
  double
  peak_change(const std::vector<ZoomLevel> &levels, const std::size_t k);

  /**
   * @brief Whether the peak changed by at most @p tolerance over each of
   * the last two levels of @p levels: the zoom's and the rounding study's
   * "twice in a row" (one small change can be a coincidence of two
   * meshes).
   */
  bool
  peak_settled(const std::vector<ZoomLevel> &levels, const double tolerance);

  /**
   * @brief Nested meshes that halve the cells around one corner's contact
   * end from level to level, the rest of the mesh kept: level 0 is the
   * scene's mesh (Studies::AdaptiveLevels), level k asks for cells of the
   * scene's corner size / 2^k along the joint within a window around the
   * zone's end and its peak on level k-1 (both sides alike: matched
   * refinement), graded by growth 1.5 away from it.
   *
   * The window follows the zone as the levels move it. Edge in a fillet:
   * from the fillet's start to beyond the edge, each extended by the
   * zone's reach into the fillet, so the peak and the edge are both
   * inside. Zone reaching the sharp corner, or open there: a tenth of
   * the zone's length around its end.
   */
  class CornerZoom
  {
  public:
    CornerZoom(const Parameters::ScenarioParameters &scene,
               const Corner::CornerSite             &site);

    /**
     * @brief Solves the next level into @p folder (mesh.msh, fem.json,
     * joint tables). Returns nothing if the solve did not converge (its
     * fem.json says what was tried).
     */
    std::optional<ZoomLevel>
    next(const Output::ResultFolder &folder);

    const std::vector<ZoomLevel> &
    levels() const;

    /**
     * @brief Whether the next level's cells would stay at or above
     * smallest_zoom_cell times the smaller block side.
     */
    bool
    can_refine() const;

  private:
    std::vector<Geometry::LocalSize>
    window(double size) const;

    const Parameters::ScenarioParameters scene;
    const Corner::CornerSite             site;
    Studies::AdaptiveLevels              adaptive;
    std::vector<ZoomLevel>               done;
    /** The previous level's joint profile (reference positions). */
    std::vector<Contact::JointNodeSample> last_joint_profile;
    double                                corner_size = 0.;
  };

  /** Growth of the requested cell size away from the zoom window (per m). */
  constexpr double zoom_growth_rate = 1.5;

  /**
   * Smallest zoom cell, relative to the smaller block side. Measured on the
   * 3-block scene with 2 cm fillets: cells of 0.38 um on 1 m blocks gave
   * the converged field, 0.19 um made the face joint's contact jump to the
   * fillet's far end with a 2.2 GPa peak (the joint pairing's and the
   * contact's tolerances are relative to the blocks: round-off, not rock).
   */
  constexpr double smallest_zoom_cell = 3e-7;
} // namespace FloorBlock::Studies
