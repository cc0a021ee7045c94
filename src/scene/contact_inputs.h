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

  /**
   * Largest 3D system that Solver/Linear solver = automatic solves
   * directly. UMFPACK's fill grows fast in 3D: on the plane-strain scene
   * (0.25 m slices, 44 factorisations) the linear solves took 6.4, 26 and
   * 117 s at 28.9k, 48.1k and 86.6k DoFs (time ~ N^2.6, 2.2 GB at 86.6k),
   * GMRES + ML 29, 54 and 109 s (~ N^1.2, 0.7 GB): even near 80k DoFs.
   */
  constexpr unsigned int max_direct_dofs_3d = 80000;

  /**
   * @brief Numerical settings; VTU files go to @p vtu_folder if not empty.
   * A 3D scene solves directly up to the smaller of Solver/Max direct DoFs
   * and max_direct_dofs_3d.
   */
  Contact::ContactSolverSettings
  contact_solver_settings(const Parameters::ScenarioParameters &scene,
                          const std::string                    &vtu_folder);
} // namespace FloorBlock::Scene
