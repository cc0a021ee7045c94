#pragma once

#include <analytic/analytic.h>
#include <parameters/scenario_parameters.h>

#include <optional>
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
    /**
     * The chapter's route to the floor's safety factor (section 6.7):
     * ClosedForms::floor_strength over Eq. 6.53's sigma_max at the face
     * joint; empty where the mechanism or Eqs. 6.51-6.53 give no answer.
     */
    std::optional<double> floor_safety_factor;
  };

  /** Every closed form of the chapter for one scene. */
  struct ClosedForms
  {
    Analytic::BlockChain         chain;
    double                       support_width;  ///< b (m)
    double                       youngs_modulus; ///< E (Pa)
    double                       floor_lift;     ///< y of Eq. 6.51 (m)
    /**
     * The rock mass's uniaxial compressive strength sigma_ci s^a (Pa,
     * Strength/): the Hoek-Brown strength at sigma_3 = 0, the stress state
     * of the floor-level corner, a free surface, that Eq. 6.53's sigma_max
     * loads along the joint.
     */
    double floor_strength = 0.;
    std::vector<MechanismResult> mechanisms;
    /// Centroid heights and rotation criterion of the no-rotation case.
    Analytic::CentroidHeights no_rotation_heights;
    /**
     * How the FEM's scene differs from the one the closed forms describe,
     * one sentence each (scene_differences()); empty: the same scene, and
     * the two may be compared.
     */
    std::vector<std::string> scene_differences;
  };

  /**
   * @brief The ways the FEM's scene is not the chapter's for these closed
   * forms: a support load that is not vertical on block tops that are not
   * level (the chapter's P_i is vertical), and a bed the FEM's uplift
   * leaves other than the bedding the closed forms stand the blocks on
   * (reading lifted: a flat bed translated or tilted under an inclined or
   * curved bedding, a tilted level bed, or a lift other than the
   * bedding's rise). Translations of a level bed (Uplift mode vertical or
   * along the dip) leave the bed's inclination, which is all the chain
   * uses, and the inclined reading is the chapter's own set-up.
   */
  std::vector<std::string>
  scene_differences(const Parameters::ScenarioParameters &scene);

  /** @brief Evaluates all three mechanisms, the centroid heights and 6.51-6.53. */
  ClosedForms
  evaluate_closed_forms(const Parameters::ScenarioParameters &scene);
} // namespace FloorBlock::Scene
