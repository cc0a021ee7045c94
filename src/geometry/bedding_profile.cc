#include <geometry/bedding_profile.h>

#include <algorithm>
#include <cmath>

namespace FloorBlock::Geometry
{
  BeddingProfile::BeddingProfile(const BeddingShape shape,
                                 const double       slope_of_plane,
                                 const double       curvature)
    : shape(shape)
    , slope_of_plane(slope_of_plane)
    , curvature(curvature)
  {}

  BeddingProfile
  BeddingProfile::uplift_profile(const AssemblyDescription &description)
  {
    return BeddingProfile(description.bedding_shape,
                          std::tan(description.inclination),
                          description.curvature);
  }

  BeddingProfile
  BeddingProfile::geometry_profile(const AssemblyDescription &description)
  {
    if (description.floor_uplift == FloorUplift::lifted_flat_bedding)
      return BeddingProfile(BeddingShape::planar, 0.0, description.curvature);
    return uplift_profile(description);
  }

  double
  BeddingProfile::height(const double x) const
  {
    if (shape == BeddingShape::planar)
      return slope_of_plane * x;
    return x > 0.0 ? x * x / curvature : 0.0;
  }

  double
  BeddingProfile::slope(const double x) const
  {
    if (shape == BeddingShape::planar)
      return slope_of_plane;
    return x > 0.0 ? 2.0 * x / curvature : 0.0;
  }

  double
  BeddingProfile::second_derivative(const double x) const
  {
    if (shape == BeddingShape::planar)
      return 0.0;
    return x > 0.0 ? 2.0 / curvature : 0.0;
  }

  double
  BeddingProfile::integral(const double x_a, const double x_b) const
  {
    if (shape == BeddingShape::planar)
      return slope_of_plane * (x_b * x_b - x_a * x_a) / 2.0;
    const auto antiderivative = [this](const double x) {
      return x > 0.0 ? x * x * x / (3.0 * curvature) : 0.0;
    };
    return antiderivative(x_b) - antiderivative(x_a);
  }

  double
  BeddingProfile::bezier_control_height(const double x_a,
                                        const double x_b,
                                        const double shift) const
  {
    const double x_low  = std::min(x_a, x_b);
    const double x_high = std::max(x_a, x_b);
    return height(x_low) + slope(x_low) * (x_high - x_low) / 2.0 + shift;
  }

  bool
  BeddingProfile::is_straight(const double x_a, const double x_b) const
  {
    return shape == BeddingShape::planar || std::max(x_a, x_b) <= 0.0;
  }
} // namespace FloorBlock::Geometry
