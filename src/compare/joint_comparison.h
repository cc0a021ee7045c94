#pragma once

#include <analytic/corner_contact.h>
#include <compare/load_check.h>
#include <contact/results.h>
#include <scene/closed_forms.h>

#include <string>
#include <vector>

namespace FloorBlock::Compare
{
  /** Whether a relative difference FEM against closed form is defined. */
  enum class DifferenceStatus
  {
    defined,
    /** The closed form has no value here (its status says why). */
    no_closed_form,
    /** The FEM increment carries no load (LoadCheck): round-off. */
    no_load,
    /** The closed form is exactly 0: the relative difference is undefined. */
    zero_closed_form,
    /** The closed forms describe another scene than the FEM's
     * (Scene::ClosedForms::scene_differences): no verdict. */
    other_scene
  };

  /** @brief "ok", "no_closed_form", "no_load", "zero_closed_form" or
   * "other_scene". */
  std::string
  to_string(const DifferenceStatus status);

  /** FEM lateral force at one vertical joint against one closed form. */
  struct ForceComparison
  {
    std::string      mechanism; ///< Scene::to_string(Mechanism)
    Analytic::Status closed_form_status = Analytic::Status::ok;
    std::string      status; ///< the closed form's status, as a word
    bool             has_value         = false;
    double           closed_form       = 0.; ///< Q_j (N/m); 0 without a value
    DifferenceStatus difference_status = DifferenceStatus::no_closed_form;
    /** (FEM - closed form) / |closed form|; 0 unless defined. */
    double relative_difference = 0.;
  };

  /**
   * Eqs. 6.51-6.53 evaluated with the FEM's own Q and own y at a vertical
   * joint, against the FEM's contact area and stresses.
   */
  struct ContactComparison
  {
    double force_over_width  = 0.;       ///< Q over b from the FEM (N)
    double relative_rotation = 0.;       ///< theta_away - theta_face (rad)
    double floor_lift        = 0.;       ///< y = L tan(relative rotation) (m)
    Analytic::CornerContact closed_form; ///< 6.51-6.53 with those inputs
    double                  fem_area        = 0.; ///< contact length x b (m^2)
    double                  fem_mean_stress = 0.; ///< Pa
    double                  fem_peak_stress = 0.; ///< pointwise (Pa)
    double                  fem_averaged_peak_stress = 0.; ///< Pa
    /** False when the increment carries no load (LoadCheck). */
    bool fem_carries_load = true;
  };

  /** Everything compared at one vertical joint in one increment. */
  struct JointComparison
  {
    unsigned int                 joint; ///< chapter number j (n = face joint)
    double                       fem_force = 0.; ///< N/m
    std::vector<ForceComparison> forces;
    ContactComparison            contact;
    LoadCheck                    load; ///< of the whole increment
  };

  /** What the closed forms were given, named beside every verdict. */
  struct ClosedFormInputs
  {
    /** alpha_i against the true horizontal (rad), block 1 (free end) first. */
    std::vector<double> inclination;
    std::vector<double> weight;          ///< W_i (N/m)
    std::vector<double> support_load;    ///< P_i (N/m), vertical
    double              floor_lift = 0.; ///< y of Eq. 6.51 at the face (m)
    /** Scene::ClosedForms::scene_differences; empty: the same scene. */
    std::vector<std::string> scene_differences;
  };

  /** @brief The inputs of @p closed_forms, for the reports. */
  ClosedFormInputs
  closed_form_inputs(const Scene::ClosedForms &closed_forms);

  /** Inputs of 6.51-6.53 that do not come from the FEM. */
  struct ContactConstants
  {
    double youngs_modulus; ///< E (Pa)
    double support_width;  ///< b (m)
    double block_width;    ///< L (m)
    double block_height;   ///< H (m)
  };

  /**
   * @brief Compares every vertical joint of one converged increment with
   * the closed forms.
   *
   * y is the FEM's own: L tan(theta_j - theta_{j+1}) from the best-fit
   * rotations of the two bodies at joint j (the face block's is 0 when it
   * is fixed); positive when the relative rotation closes the top corners,
   * as 6.51 assumes. Where it is not positive, corner_contact() reports
   * zero_floor_lift and the record says so. An increment that carries no
   * load (check_load() with constants.youngs_modulus) is not compared: its
   * forces are round-off. Nor is a scene the closed forms do not describe
   * (DifferenceStatus::other_scene); the contact comparison, which feeds
   * the FEM's own Q and y to Eqs. 6.51-6.53, is made in every case.
   */
  std::vector<JointComparison>
  compare_vertical_joints(const Contact::IncrementResult &increment,
                          const Scene::ClosedForms       &closed_forms,
                          const ContactConstants         &constants);
} // namespace FloorBlock::Compare
