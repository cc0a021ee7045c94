#include <analytic/status.h>

namespace FloorBlock::Analytic
{
  std::string
  describe(const Status status)
  {
    switch (status)
      {
        case Status::ok:
          return "The closed form has a finite, admissible answer.";
        case Status::invalid_input:
          return "An input is not finite or out of range (negative load, "
                 "non-positive block size, friction angle outside "
                 "[0, 90) degrees or inclination outside (-90, 90) "
                 "degrees).";
        case Status::self_locking:
          return "The blocks are self-locking: bedding and joint friction "
                 "together exceed what any finite lateral force can "
                 "overcome, so Q would be infinite.";
        case Status::rotation_denominator_nonpositive:
          return "L - H tan(phi_h) <= 0: the blocks are too slender for "
                 "their bedding friction to let them rotate about the "
                 "uphill corner, so the rotation mechanism cannot form.";
        case Status::vertical_friction_exceeded:
          return "Rotation without vertical slip would need more shear "
                 "on a vertical joint than its friction can carry; the "
                 "blocks slip along the vertical joints instead.";
        case Status::joint_opens:
          return "A vertical joint would carry tension (Q < 0): the "
                 "blocks separate and the chain model does not apply.";
        case Status::base_lifts_off:
          return "A block base would carry tension (N < 0): the block "
                 "lifts off the bedding and the model does not apply.";
        case Status::normal_force_outside_base:
          return "The base normal force would act outside the block "
                 "base: the block tips and the assumed mechanism does "
                 "not apply.";
        case Status::zero_floor_lift:
          return "The blocks rotate against each other so that the joint "
                 "closes at its foot, not at floor level (or it carries no "
                 "force): there is no corner contact at floor level.";
        case Status::whole_joint_in_contact:
          return "The blocks rotate against each other too little for a "
                 "corner contact: the whole joint face is in contact, "
                 "with the trapezoidal stress of the same compatibility "
                 "(A = bH, sigma_avg = Q/(bH)).";
      }
    return "Unknown status.";
  }

  std::string
  to_string(const Status status)
  {
    switch (status)
      {
        case Status::ok:
          return "ok";
        case Status::invalid_input:
          return "invalid_input";
        case Status::self_locking:
          return "self_locking";
        case Status::rotation_denominator_nonpositive:
          return "rotation_denominator_nonpositive";
        case Status::vertical_friction_exceeded:
          return "vertical_friction_exceeded";
        case Status::joint_opens:
          return "joint_opens";
        case Status::base_lifts_off:
          return "base_lifts_off";
        case Status::normal_force_outside_base:
          return "normal_force_outside_base";
        case Status::zero_floor_lift:
          return "zero_floor_lift";
        case Status::whole_joint_in_contact:
          return "whole_joint_in_contact";
      }
    return "unknown";
  }
} // namespace FloorBlock::Analytic
