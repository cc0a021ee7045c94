#include <common/input_error.h>
#include <geometry/assembly_description.h>
#include <geometry/bedding_profile.h>
#include <geometry/body_outline.h>
#include <geometry/ids.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace FloorBlock::Geometry
{
  namespace
  {
    std::string
    text(const double value)
    {
      std::ostringstream stream;
      stream << value;
      return stream.str();
    }

    void
    require_positive_length(const std::string &parameter, const double value)
    {
      if (!(std::isfinite(value) && value > 0.0))
        throw InputError(parameter,
                         text(value) + " m",
                         "a finite length > 0 (units: m)");
    }

    /** Steepest inclination of the geometry's bedding under the blocks. Units:
     * rad. */
    double
    steepest_inclination(const AssemblyDescription &description)
    {
      const BeddingProfile profile =
        BeddingProfile::geometry_profile(description);
      const double x_free = description.n_blocks * description.block_width;
      return std::atan(std::max(std::abs(profile.slope(x_free)),
                                std::abs(profile.slope(0.0))));
    }

    /** Block count and sizes. */
    void
    validate_sizes(const AssemblyDescription &description)
    {
      if (description.n_blocks < 1 || description.n_blocks > Ids::max_n_blocks)
        throw InputError("Geometry/Number of blocks",
                         std::to_string(description.n_blocks),
                         "an integer from 1 to " +
                           std::to_string(Ids::max_n_blocks));
      require_positive_length("Geometry/Block width", description.block_width);
      require_positive_length("Geometry/Block height",
                              description.block_height);
      require_positive_length("Geometry/Face block width",
                              description.face_block_width);
      require_positive_length("Geometry/Base thickness",
                              description.base_thickness);
    }

    /** The bedding: its inclination or curvature. */
    void
    validate_bedding(const AssemblyDescription &description)
    {
      const double max_degrees = max_bedding_inclination * 180.0 / M_PI;
      if (description.bedding_shape == BeddingShape::planar &&
          !(std::isfinite(description.inclination) &&
            std::abs(description.inclination) <= max_bedding_inclination))
        throw InputError("Geometry/Inclination",
                         text(description.inclination) + " rad",
                         "|alpha| <= " + text(max_bedding_inclination) +
                           " rad (" + text(max_degrees) +
                           " deg): steeper bedding leaves blocks too acute "
                           "to mesh");
      if (description.bedding_shape == BeddingShape::parabolic)
        {
          if (!(std::isfinite(description.curvature) &&
                description.curvature > 0.0))
            throw InputError("Geometry/Curvature",
                             text(description.curvature) + " m",
                             "k > 0 in y = x^2/k (units: m)");
          if (steepest_inclination(description) > max_bedding_inclination)
            {
              // Slope 2x/k at the free end x = nL must stay below tan(limit).
              const double max_free_end =
                std::tan(max_bedding_inclination) * description.curvature / 2.0;
              const unsigned int fitting = static_cast<unsigned int>(
                std::floor(max_free_end / description.block_width));
              throw InputError(
                "Geometry/Number of blocks",
                std::to_string(description.n_blocks),
                "at most " + std::to_string(fitting) + " blocks of width " +
                  text(description.block_width) + " m fit on y = x^2/" +
                  text(description.curvature) +
                  " before the bedding is steeper than " + text(max_degrees) +
                  " deg; use fewer blocks or a larger curvature k");
            }
        }
    }

    /** The corner rounding radius against the blocks and the bedding. */
    void
    validate_rounding(const AssemblyDescription &description)
    {
      const double radius        = description.corner_rounding_radius;
      const double smallest_side = std::min({description.block_width,
                                             description.block_height,
                                             description.face_block_width});
      if (!(std::isfinite(radius) && radius >= 0.0 &&
            radius < smallest_side / 2.0))
        throw InputError("Geometry/Corner rounding radius",
                         text(radius) + " m",
                         "0 (sharp) <= r < " + text(smallest_side / 2.0) +
                           " m, half the smallest block side");
      if (description.bedding_shape == BeddingShape::parabolic &&
          radius >= description.curvature / 2.0)
        throw InputError("Geometry/Corner rounding radius",
                         text(radius) + " m",
                         "r < k/2 = " + text(description.curvature / 2.0) +
                           " m, the smallest radius of curvature of the "
                           "bedding");
    }

    /** The mesh sizes. */
    void
    validate_mesh_sizes(const AssemblyDescription &description)
    {
      const double corner_size = description.mesh_corner_size;
      const double smallest_block_side =
        std::min(description.block_width, description.block_height);
      const double min_corner_size =
        min_relative_corner_size * smallest_block_side;
      if (!(std::isfinite(corner_size) && corner_size >= min_corner_size &&
            corner_size <= smallest_block_side))
        throw InputError("Mesh/Corner size",
                         text(corner_size) + " m",
                         text(min_corner_size) +
                           " m <= size <= " + text(smallest_block_side) +
                           " m (between 1e-3 and 1 times the smaller block "
                           "side)");
      const double far_size = description.mesh_far_size;
      const double scene_extent =
        description.n_blocks * description.block_width +
        description.face_block_width;
      if (!(std::isfinite(far_size) && far_size >= corner_size &&
            far_size <= scene_extent))
        throw InputError("Mesh/Far size",
                         text(far_size) + " m",
                         "Mesh/Corner size (" + text(corner_size) +
                           " m) <= size <= " + text(scene_extent) +
                           " m, the scene width");
      constexpr double max_growth_rate = 3.0; // beyond, quads degrade badly
      if (!(std::isfinite(description.mesh_growth_rate) &&
            description.mesh_growth_rate > 1.0 &&
            description.mesh_growth_rate <= max_growth_rate))
        throw InputError("Mesh/Growth rate",
                         text(description.mesh_growth_rate),
                         "1 < rate <= " + text(max_growth_rate) +
                           " (ratio of neighbouring cell sizes)");
    }
  } // namespace

  void
  validate(const AssemblyDescription &description)
  {
    validate_sizes(description);
    validate_bedding(description);
    validate_rounding(description);
    validate_mesh_sizes(description);
    // Fillets that do not fit are refused by the outline builder itself.
    if (description.corner_rounding_radius > 0.0)
      build_outline(description);
  }
} // namespace FloorBlock::Geometry
