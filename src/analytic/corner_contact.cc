#include <analytic/corner_contact.h>
#include <analytic/input_checks.h>

#include <cmath>

namespace FloorBlock::Analytic
{
  using Internal::is_positive;

  CornerContact
  corner_contact(const double lateral_force_over_width,
                 const double floor_lift,
                 const double youngs_modulus,
                 const double support_width,
                 const double block_width,
                 const double block_height)
  {
    CornerContact contact;
    const bool    inputs_ok =
      std::isfinite(lateral_force_over_width) &&
      lateral_force_over_width >= 0. && std::isfinite(floor_lift) &&
      is_positive(youngs_modulus) && is_positive(support_width) &&
      is_positive(block_width) && is_positive(block_height);
    if (!inputs_ok)
      {
        contact.status = Status::invalid_input;
        return contact;
      }
    // Symbols of 6.51-6.53: Q force over b (N), y lift (m), E (Pa).
    const double Q = lateral_force_over_width;
    const double y = floor_lift;
    const double E = youngs_modulus;
    const double b = support_width;
    const double L = block_width;
    const double H = block_height;
    if (Q == 0. && y <= 0.)
      {
        contact.status = Status::zero_floor_lift;
        return contact;
      }
    // The lift at which the triangle of 6.51 just reaches the block's foot
    // (c = H): Q = E (y/L) H^2 b / (2 L).
    const double whole_joint_lift = 2. * Q * L * L / (E * b * H * H);
    if (y > whole_joint_lift)
      {
        contact.contact_length = L * std::sqrt(2. * Q / (y * E * b));
        contact.contact_area   = b * contact.contact_length;
        contact.average_stress = std::sqrt(y * E * Q / (2. * b * L * L));
        contact.max_stress     = 2. * contact.average_stress;
      }
    else if (y >= -whole_joint_lift)
      {
        // The same compatibility over the whole face: a uniform closure
        // delta_0 plus the rotation's theta (H - z), sigma(z) = E delta/L,
        // carrying Q over b H: sigma = Q/(bH) + E (y/L) (H/2 - z)/L. Its
        // largest value is at floor level for y > 0, at the foot for y < 0.
        contact.status         = Status::whole_joint_in_contact;
        contact.contact_length = H;
        contact.contact_area   = b * H;
        contact.average_stress = Q / (b * H);
        contact.max_stress =
          contact.average_stress + E * std::abs(y) * H / (2. * L * L);
      }
    else
      {
        contact.status = Status::zero_floor_lift;
        return contact;
      }
    // Finite inputs near the limits of double can still overflow the
    // products above: report that instead of returning inf.
    if (!std::isfinite(contact.contact_length) ||
        !std::isfinite(contact.contact_area) ||
        !std::isfinite(contact.average_stress) ||
        !std::isfinite(contact.max_stress))
      return CornerContact{Status::invalid_input, 0., 0., 0., 0.};
    return contact;
  }
} // namespace FloorBlock::Analytic
