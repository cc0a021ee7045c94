#pragma once

#include <analytic/analytic.h>
#include <parameters/scenario_parameters.h>

#include <string>
#include <vector>

namespace FloorBlock::Scene
{
  /** The three mechanisms of the chapter, by their output names. */
  enum class Mechanism
  {
    no_rotation,               ///< 6.1-6.13, 6.22-6.24
    rotation_no_vertical_slip, ///< 6.26-6.38
    rotation_vertical_slip     ///< 6.39-6.46
  };

  /** @brief "no_rotation", ... as used in JSON keys and CSV columns. */
  std::string
  to_string(const Mechanism mechanism);

  /** One mechanism evaluated for a scene, with its corner contact at the face.
   */
  struct MechanismResult
  {
    Mechanism             mechanism;
    Analytic::ChainForces forces; ///< per metre of face
    /// Q_n over the support width b (N): the Q of Eq. 6.51; 0 if no answer.
    double                  face_force_over_width = 0.;
    Analytic::CornerContact contact; ///< Eqs. 6.51-6.53 at the face joint
  };

  /** Every closed form of the chapter for one scene. */
  struct ClosedForms
  {
    Analytic::BlockChain         chain;
    double                       support_width;  ///< b (m)
    double                       youngs_modulus; ///< E (Pa)
    double                       floor_lift;     ///< y of Eq. 6.51 (m)
    std::vector<MechanismResult> mechanisms;
    /// Centroid heights and rotation criterion of the no-rotation case.
    Analytic::CentroidHeights no_rotation_heights;
  };

  /** @brief Evaluates all three mechanisms, the centroid heights and 6.51-6.53. */
  ClosedForms
  evaluate_closed_forms(const Parameters::ScenarioParameters &scene);
} // namespace FloorBlock::Scene
