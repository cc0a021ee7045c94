#include <strength/critical_distance.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace FloorBlock::Strength
{
  namespace
  {
    void
    require_path_to(const std::vector<PathSample> &path, const double reach)
    {
      if (path.size() < 2 || path.front().distance != 0. || !(reach > 0.) ||
          path.back().distance < reach)
        throw std::invalid_argument(
          "critical distance: the path must start at the hot spot and "
          "reach the distance asked for");
      for (std::size_t k = 1; k < path.size(); ++k)
        if (!(path[k].distance > path[k - 1].distance))
          throw std::invalid_argument(
            "critical distance: path distances must increase");
    }

    /** The linear interpolant between samples k-1 and k at @p distance. */
    PlaneStrainStress
    between(const PathSample &a, const PathSample &b, const double distance)
    {
      const double t = (distance - a.distance) / (b.distance - a.distance);
      return (1. - t) * a.stress + t * b.stress;
    }

    /** Calls @p add(a, b) for every piece [a, b] of the linear interpolant
     * of @p path over [0, length] (the last one cut at length). */
    template <typename Add>
    void
    for_each_piece(const std::vector<PathSample> &path,
                   const double                   length,
                   const Add                     &add)
    {
      for (std::size_t k = 1; k < path.size(); ++k)
        {
          const PathSample &a = path[k - 1];
          if (a.distance >= length)
            break;
          const double end = std::min(path[k].distance, length);
          add(a, PathSample{end, between(a, path[k], end)});
        }
    }
  } // namespace

  double
  critical_distance(const double fracture_toughness,
                    const double tensile_strength)
  {
    const double ratio = fracture_toughness / tensile_strength;
    return ratio * ratio / M_PI;
  }

  PlaneStrainStress
  point_method_stress(const std::vector<PathSample> &path, const double length)
  {
    const double distance = 0.5 * length;
    require_path_to(path, distance);
    std::size_t k = 1;
    while (path[k].distance < distance)
      ++k;
    return between(path[k - 1], path[k], distance);
  }

  PlaneStrainStress
  line_method_stress(const std::vector<PathSample> &path, const double length)
  {
    require_path_to(path, length);
    PlaneStrainStress integral;
    for_each_piece(path, length, [&](const PathSample &a, const PathSample &b) {
      integral =
        integral + (0.5 * (b.distance - a.distance)) * (a.stress + b.stress);
    });
    return (1. / length) * integral;
  }

  PlaneStrainStress
  area_method_stress(const std::vector<std::vector<PathSample>> &rays,
                     const double                                length)
  {
    if (rays.empty())
      throw std::invalid_argument("critical distance: no rays for the area");
    PlaneStrainStress sum;
    for (const std::vector<PathSample> &ray : rays)
      {
        require_path_to(ray, length);
        // Over a segment [a, b] where the stress is linear,
        // int sigma rho drho = (b - a)/6 [sigma_a (2a + b) + sigma_b (a + 2b)].
        PlaneStrainStress moment;
        for_each_piece(ray,
                       length,
                       [&](const PathSample &a, const PathSample &b) {
                         moment = moment +
                                  ((b.distance - a.distance) / 6.) *
                                    ((2. * a.distance + b.distance) * a.stress +
                                     (a.distance + 2. * b.distance) * b.stress);
                       });
        sum = sum + (2. / (length * length)) * moment;
      }
    return (1. / rays.size()) * sum;
  }
} // namespace FloorBlock::Strength
