#pragma once

#include <parameters/scenario_parameters.h>
#include <scene/closed_forms.h>

#include <string>
#include <vector>

namespace FloorBlock::Scene
{
  /**
   * One evaluated point of a chapter figure: the scene's closed forms with
   * the figure's varied inputs (bedding shape, friction angles, support load)
   * set, everything else as in the scene.
   */
  struct FigurePoint
  {
    std::string figure;            ///< e.g. "fig6_5"
    double      curvature;         ///< k (m); 0 for a planar bedding
    double      bedding_friction;  ///< phi_h (rad)
    double      vertical_friction; ///< phi_v (rad)
    double      support_load;      ///< N, one support
    ClosedForms closed_forms;
    /// The scene with this point's inputs set, for the FEM.
    Parameters::ScenarioParameters scene;

    /** @brief A stable name, used as the case's file name in FEM sweeps. */
    std::string
    id() const;
  };

  /**
   * @brief Figures 6.5 (planar, the scene's inclination), 6.6 (y = x^2/400)
   * and 6.7 (y = x^2/200): Q at the face for bedding friction 10-35 deg
   * (step 5) and vertical friction 15-45 deg (step 10), at the scene's
   * support load.
   */
  std::vector<FigurePoint>
  lateral_force_figures(const Parameters::ScenarioParameters &scene);

  /**
   * @brief Figures 6.10/6.11: sigma_max (Eq. 6.53) at the face for k in
   * {400, 200, 100, 50} m, bedding friction 10-35 deg (step 5) and support
   * load 400-900 t (step 100), at the scene's vertical friction.
   */
  std::vector<FigurePoint>
  floor_stress_figures(const Parameters::ScenarioParameters &scene);
} // namespace FloorBlock::Scene
