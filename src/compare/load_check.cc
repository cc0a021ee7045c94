#include <compare/load_check.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Compare
{
  LoadCheck
  check_load(const Contact::IncrementResult &increment,
             const double                    youngs_modulus)
  {
    LoadCheck check;
    check.largest_force = std::max(increment.balance.applied_load.norm(),
                                   increment.balance.support_reaction.norm());
    for (const Contact::JointReport &joint : increment.joints)
      check.largest_force = std::max({check.largest_force,
                                      std::abs(joint.normal_force),
                                      std::abs(joint.shear_force)});
    double largest_translation = 0.;
    for (const auto &[material, motion] : increment.motions)
      largest_translation =
        std::max(largest_translation, motion.translation.norm());
    check.round_off_force =
      round_off_force_fraction * youngs_modulus * largest_translation;
    return check;
  }
} // namespace FloorBlock::Compare
