#pragma once

#include <scene/closed_forms.h>

namespace FloorBlock::Output
{
  /**
   * @brief Whether a mechanism's chain forces may be reported as numbers.
   *
   * A mechanism whose status is not ok still carries the forces its
   * equations produced (e.g. a negative Q where a joint would open); they
   * are no answer of the model, so every CSV leaves them empty and every
   * plot leaves them out.
   */
  inline bool
  has_admissible_forces(const Scene::MechanismResult &entry)
  {
    return entry.forces.status == Analytic::Status::ok &&
           !entry.forces.lateral_force.empty();
  }

  /**
   * @brief Status of Eqs. 6.51-6.53 at the face joint for one mechanism.
   *
   * The corner contact is evaluated from the mechanism's Q at the face; when
   * the mechanism itself is not ok that Q is no answer, so its status, not
   * the contact formula's own, is the status of the contact values.
   */
  inline Analytic::Status
  face_contact_status(const Scene::MechanismResult &entry)
  {
    return entry.forces.status != Analytic::Status::ok ? entry.forces.status :
                                                         entry.contact.status;
  }

  /** @brief Whether Eqs. 6.51-6.53 at the face may be reported as numbers. */
  inline bool
  has_admissible_contact(const Scene::MechanismResult &entry)
  {
    return has_admissible_forces(entry) &&
           Analytic::has_contact_values(face_contact_status(entry));
  }
} // namespace FloorBlock::Output
