#include <compare/governing_joints.h>
#include <compare/joint_name.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Compare
{
  namespace
  {
    /** Relative difference below which two joints carry the same value. */
    constexpr double same_value_tolerance = 1e-9;

    struct Figure
    {
      const char *key;
      const char *description;
      /** Only vertical joints carry the chapter's Q. */
      bool   vertical_only;
      double Contact::JointReport::*value;
    };

    constexpr Figure figures[] = {
      {"Q_N_per_m",
       "lateral force Q",
       true,
       &Contact::JointReport::normal_force},
      {"sigma_max_Pa",
       "pointwise peak normal stress",
       false,
       &Contact::JointReport::peak_normal_stress},
      {"sigma_max_averaged_Pa",
       "averaged peak normal stress",
       false,
       &Contact::JointReport::averaged_peak_normal_stress},
      {"sigma_mean_Pa",
       "mean contact stress",
       false,
       &Contact::JointReport::mean_normal_stress}};
  } // namespace

  bool
  GoverningJoint::is_face_joint() const
  {
    return joint == face_joint;
  }

  std::vector<GoverningJoint>
  governing_joints(const Contact::IncrementResult &increment,
                   const unsigned int              n_blocks)
  {
    std::vector<GoverningJoint> governing;
    const std::string           face = face_joint_name(n_blocks);
    const auto                  face_report =
      std::find_if(increment.joints.begin(),
                   increment.joints.end(),
                   [&face](const auto &joint) { return joint.name == face; });
    for (const Figure &figure : figures)
      {
        // The face joint unless another joint carries more by more than
        // round-off: unloaded blocks pass the face joint's Q on unchanged,
        // to 1e-12 of it.
        const Contact::JointReport *largest =
          face_report != increment.joints.end() ? &*face_report : nullptr;
        for (const Contact::JointReport &joint : increment.joints)
          if ((!figure.vertical_only ||
               parse_joint_name(joint.name).kind == "vertical") &&
              (!largest ||
               joint.*figure.value >
                 largest->*figure.value +
                   same_value_tolerance * std::abs(largest->*figure.value)))
            largest = &joint;
        if (!largest)
          continue;
        GoverningJoint entry;
        entry.figure      = figure.key;
        entry.description = figure.description;
        entry.joint       = largest->name;
        entry.value       = largest->*figure.value;
        entry.x           = largest->peak_position[0];
        entry.y           = largest->peak_position[1];
        entry.face_joint  = face;
        entry.face_value  = face_report != increment.joints.end() ?
                              (*face_report).*figure.value :
                              0.;
        governing.push_back(entry);
      }
    return governing;
  }
} // namespace FloorBlock::Compare
