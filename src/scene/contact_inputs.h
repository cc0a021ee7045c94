#pragma once

#include <contact/contact_problem.h>
#include <parameters/scenario_parameters.h>
#include <scene/floor_contact_problem.h>

#include <string>

namespace FloorBlock::Scene
{
  /**
   * @brief The physics of a scene for the contact solver: rock, joints,
   * support pressures (the same P_i per metre as the closed forms, spread
   * over the block top, so p_i = P_i / L), and the uplift stage.
   *
   * Uplift modes (Loading/Uplift mode), with lift = Loading/Floor lift:
   * - vertical: the base moves up by lift;
   * - dip toward/away from face: the base moves by lift along the bedding
   *   chord under the blocks (planar: alpha; parabolic: the chord from the
   *   face to x = nL, slope nL/k);
   * - tilt: the base turns about its free-end point (x = nL on the bedding)
   *   so that the face end rises by lift;
   * - parabola: the base bends into u_y = lift (x/nL)^2, i.e. y = x^2/k
   *   with k = (nL)^2/lift.
   */
  FloorProblemSettings
  floor_problem_settings(const Parameters::ScenarioParameters &scene);

  /** @brief Numerical settings; VTU files go to @p vtu_folder if not empty. */
  Contact::ContactSolverSettings
  contact_solver_settings(const Parameters::ScenarioParameters &scene,
                          const std::string &                   vtu_folder);
} // namespace FloorBlock::Scene
