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
      min_relative_corner_size *
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
                             " m (1e-3 times the smaller block side)");
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
                      local.size +
                        (growth_rate - 1.0) *
                          std::hypot(point.x - local.position.x,
                                     point.y - local.position.y));
    return size;
  }

  double
  local_size_class(const double size)
  {
    return std::exp2(std::floor(classes_per_octave * std::log2(size)) /
                     classes_per_octave);
  }

  int
  add_local_size_field(const std::vector<LocalSize> &local_sizes,
                       const double                  growth_rate)
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
        const int graded = field::add("MathEval");
        field::setString(graded,
                         "F",
                         text(size) + " + " + text(growth_rate - 1.0) +
                           " * F" + std::to_string(distance));
        class_fields.push_back(graded);
      }
    const int minimum = field::add("Min");
    field::setNumbers(minimum, "FieldsList", class_fields);
    return minimum;
  }
} // namespace FloorBlock::Geometry
