#pragma once

#include <scene/chapter_figures.h>

#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /**
   * @brief One CSV row per figure point: the varied inputs and the scene
   * rock's strength (ClosedForms::floor_strength), then per mechanism its
   * status, Q at the face (per metre and over b), the corner stress of
   * Eqs. 6.51-6.53 and the chapter's safety factor sigma_c / sigma_max.
   * Empty cells where a mechanism has no finite, admissible answer; its
   * status columns say why.
   */
  std::string
  sweep_csv(const std::vector<Scene::FigurePoint> &points);

  /**
   * @brief gnuplot script for one of Figures 6.5-6.7: Q over b at the face
   * (kN) against bedding friction, one curve per vertical friction, one
   * panel per mechanism.
   */
  std::string
  lateral_force_plot(const std::vector<Scene::FigurePoint> &points,
                     const std::string                     &figure,
                     const std::string                     &title);

  /**
   * @brief gnuplot script for Figures 6.10/6.11 at one curvature: sigma_max
   * (MPa) against bedding friction, one curve per support load, one panel
   * per mechanism, and the scene rock's strength sigma_c as a dashed line:
   * the points above it have FS = sigma_c / sigma_max < 1.
   */
  std::string
  floor_stress_plot(const std::vector<Scene::FigurePoint> &points,
                    const double                           curvature);
} // namespace FloorBlock::Output
