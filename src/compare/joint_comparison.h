#pragma once

#include <analytic/corner_contact.h>
#include <contact/results.h>
#include <scene/closed_forms.h>

#include <string>
#include <vector>

namespace FloorBlock::Compare
{
  /** FEM lateral force at one vertical joint against one closed form. */
  struct ForceComparison
  {
    std::string mechanism;     ///< Scene::to_string(Mechanism)
    std::string status;        ///< the closed form's status
    bool        has_value = false;
    double      closed_form = 0.; ///< Q_j (N/m); 0 without a value
    double      relative_difference = 0.; ///< (FEM - closed form) / closed form
  };

  /**
   * Eqs. 6.51-6.53 evaluated with the FEM's own Q and own y at a vertical
   * joint, against the FEM's contact area and stresses.
   */
  struct ContactComparison
  {
    double                  force_over_width = 0.; ///< Q over b from the FEM (N)
    double                  relative_rotation = 0.; ///< theta_away - theta_face (rad)
    double                  floor_lift = 0.; ///< y = L tan(relative rotation) (m)
    Analytic::CornerContact closed_form;     ///< 6.51-6.53 with those inputs
    double                  fem_area = 0.;   ///< contact length x b (m^2)
    double                  fem_mean_stress = 0.;     ///< Pa
    double                  fem_peak_stress = 0.;     ///< pointwise (Pa)
    double                  fem_averaged_peak_stress = 0.; ///< Pa
  };

  /** Everything compared at one vertical joint in one increment. */
  struct JointComparison
  {
    unsigned int                 joint; ///< chapter number j (n = face joint)
    double                       fem_force = 0.; ///< N/m
    std::vector<ForceComparison> forces;
    ContactComparison            contact;
  };

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
   * zero_floor_lift and the record says so.
   */
  std::vector<JointComparison>
  compare_vertical_joints(const Contact::IncrementResult &increment,
                          const Scene::ClosedForms &      closed_forms,
                          const ContactConstants &        constants);
} // namespace FloorBlock::Compare
