#include <common/input_error.h>
#include <geometry/local_size_field.h>

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace FloorBlock::Geometry
{
  namespace
  {
    /** Classes per halving of the size (see local_size_class()). */
    constexpr double classes_per_octave = 4.0;

    std::string
    text(const double value)
    {
      std::ostringstream stream;
      stream.precision(17);
      stream << value;
      return stream.str();
    }
  } // namespace

  void
  validate_local_sizes(const std::vector<LocalSize> &local_sizes,
                       const AssemblyDescription    &description)
  {
    const double smallest_size =
      min_relative_local_size *
      std::min(description.block_width, description.block_height);
    for (const LocalSize &local : local_sizes)
      {
        const std::string where = "local element size at (" +
                                  text(local.position.x) + ", " +
                                  text(local.position.y) + ") m";
        if (!(std::isfinite(local.position.x) &&
              std::isfinite(local.position.y)))
          throw InputError(where, "position", "finite coordinates (m)");
        if (!(std::isfinite(local.size) && local.size >= smallest_size))
          throw InputError(where,
                           text(local.size) + " m",
                           "size >= " + text(smallest_size) +
                             " m (2.5e-4 times the smaller block side)");
      }
  }

  double
  local_size_at(const std::vector<LocalSize> &local_sizes,
                const double                  growth_rate,
                const Point2                 &point)
  {
    double size = std::numeric_limits<double>::max();
    for (const LocalSize &local : local_sizes)
      size = std::min(size,
                      graded_size(local,
                                  growth_rate,
                                  std::hypot(point.x - local.position.x,
                                             point.y - local.position.y)));
    return size;
  }

  double
  graded_size(const LocalSize &local,
              const double     growth_rate,
              const double     distance)
  {
    return local.size + (growth_rate - 1.0) * distance;
  }

  double
  local_size_class(const double size)
  {
    return std::exp2(std::floor(classes_per_octave * std::log2(size)) /
                     classes_per_octave);
  }

  int
  add_local_size_field(const std::vector<LocalSize> &local_sizes,
                       const double                  growth_rate,
                       const double                  largest_size)
  {
    namespace field = gmsh::model::mesh::field;
    if (local_sizes.empty())
      return -1;

    std::map<double, std::vector<double>> points_of_class;
    for (const LocalSize &local : local_sizes)
      points_of_class[local_size_class(local.size)].push_back(
        gmsh::model::occ::addPoint(local.position.x, local.position.y, 0.0));
    gmsh::model::occ::synchronize();

    std::vector<double> class_fields;
    for (const auto &[size, point_tags] : points_of_class)
      {
        const int distance = field::add("Distance");
        field::setNumbers(distance, "NodesList", point_tags);
        // Threshold (linear from LcMin at distance 0 to LcMax at DistMax)
        // is size + (g - 1) d up to largest_size, evaluated in compiled
        // code: a MathEval expression per class made re-meshing with a
        // thousand requests several times slower. Gmsh 4.8 option names.
        const int graded = field::add("Threshold");
        field::setNumber(graded, "IField", distance);
        field::setNumber(graded, "LcMin", size);
        field::setNumber(graded, "LcMax", std::max(largest_size, size));
        field::setNumber(graded, "DistMin", 0.0);
        field::setNumber(graded,
                         "DistMax",
                         std::max(largest_size - size, 0.0) /
                             (growth_rate - 1.0) +
                           std::numeric_limits<double>::min());
        class_fields.push_back(graded);
      }
    const int minimum = field::add("Min");
    field::setNumbers(minimum, "FieldsList", class_fields);
    return minimum;
  }
} // namespace FloorBlock::Geometry
