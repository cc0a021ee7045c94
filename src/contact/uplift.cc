#include <contact/uplift.h>

#include <cmath>

namespace FloorBlock::Contact
{
  template <int dim>
  dealii::Tensor<1, dim>
  uplift_displacement(const UpliftSettings     &settings,
                      const double              stage_factor,
                      const dealii::Point<dim> &position)
  {
    dealii::Tensor<1, dim> displacement;
    const double           dx = position[0] - settings.pivot_x;
    const double           dy = position[1] - settings.pivot_y;
    switch (settings.mode)
      {
        case UpliftMotion::vertical_translation:
          displacement[1] = stage_factor * settings.magnitude;
          break;
        case UpliftMotion::dip_translation:
          displacement[0] =
            stage_factor * settings.magnitude * std::cos(settings.dip_angle);
          displacement[1] =
            stage_factor * settings.magnitude * std::sin(settings.dip_angle);
          break;
          case UpliftMotion::tilt: {
            const double angle = stage_factor * settings.magnitude;
            displacement[0] = std::cos(angle) * dx - std::sin(angle) * dy - dx;
            displacement[1] = std::sin(angle) * dx + std::cos(angle) * dy - dy;
            break;
          }
        case UpliftMotion::parabola:
          // Behind the vertex (under the face block) the parabola is
          // continued by its horizontal tangent, as the geometry module
          // does for the bedding profile.
          if (settings.magnitude != 0. && dx > 0.)
            displacement[1] = stage_factor * dx * dx / settings.magnitude;
          break;
        case UpliftMotion::slope:
          // Continued horizontally behind the pivot, as the parabola.
          if (dx > 0.)
            displacement[1] = stage_factor * dx * settings.magnitude;
          break;
      }
    return displacement;
  }

  template dealii::Tensor<1, 2>
  uplift_displacement(const UpliftSettings &,
                      const double,
                      const dealii::Point<2> &);
  template dealii::Tensor<1, 3>
  uplift_displacement(const UpliftSettings &,
                      const double,
                      const dealii::Point<3> &);
} // namespace FloorBlock::Contact
