#include <analytic/hertz.h>
#include <analytic/input_checks.h>

#include <cmath>

namespace FloorBlock::Analytic
{
  using Internal::is_positive;

  HertzLineContact
  hertz_line_contact(const double line_load,
                     const double radius,
                     const double contact_modulus)
  {
    if (!is_positive(line_load) || !is_positive(radius) ||
        !is_positive(contact_modulus))
      return HertzLineContact{Status::invalid_input, 0., 0.};
    HertzLineContact contact;
    contact.half_width =
      std::sqrt(4. * line_load * radius / (M_PI * contact_modulus));
    contact.peak_pressure = 2. * line_load / (M_PI * contact.half_width);
    // Positive finite inputs near the limits of double can still
    // overflow or underflow the products above.
    if (!is_positive(contact.half_width) || !is_positive(contact.peak_pressure))
      return HertzLineContact{Status::invalid_input, 0., 0.};
    return contact;
  }

  HertzAxisStress
  hertz_axis_stress(const double peak_pressure,
                    const double half_width,
                    const double depth)
  {
    const double a      = half_width;
    const double z      = depth;
    const double radius = std::sqrt(a * a + z * z);
    return {-peak_pressure / a * ((a * a + 2. * z * z) / radius - 2. * z),
            -peak_pressure * a / radius};
  }
} // namespace FloorBlock::Analytic
