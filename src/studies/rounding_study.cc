#include <scene/mesh_sizing.h>

#include <fmt/format.h>
#include <studies/rounding_study.h>

#include <cmath>

namespace FloorBlock::Studies
{
  namespace
  {
    /** Least-squares slope of log y against log x. */
    double
    log_log_slope(const std::vector<double> &x, const std::vector<double> &y)
    {
      const double n  = static_cast<double>(x.size());
      double       sx = 0., sy = 0., sxx = 0., sxy = 0.;
      for (std::size_t k = 0; k < x.size(); ++k)
        {
          const double lx = std::log(x[k]), ly = std::log(y[k]);
          sx += lx;
          sy += ly;
          sxx += lx * lx;
          sxy += lx * ly;
        }
      const double denominator = n * sxx - sx * sx;
      return denominator > 0. ? (n * sxy - sx * sy) / denominator : 0.;
    }
  } // namespace

  RoundingPoint
  rounding_point(const double                  radius,
                 const std::vector<ZoomLevel> &levels,
                 const double                  tolerance)
  {
    RoundingPoint point;
    point.radius   = radius;
    point.n_levels = static_cast<unsigned int>(levels.size());
    if (levels.empty())
      return point;
    const ZoomLevel &last    = levels.back();
    point.peak               = last.profile.peak_traction;
    point.averaged_peak      = last.averaged_peak_stress;
    point.contact_length     = last.closed_length;
    point.edge_beyond_corner = last.profile.edge_beyond_corner;
    point.n_dofs             = last.n_dofs;
    point.smallest_size      = last.requested_size;
    for (const auto &level : levels)
      point.wall_time += level.wall_time;
    const std::size_t n = levels.size();
    if (n >= 2)
      point.last_change = peak_change(levels, n - 1);
    point.converged = peak_settled(levels, tolerance) &&
                      last.requested_size <= last.profile.edge_beyond_corner /
                                               smallest_cells_in_fillet_contact;
    return point;
  }

  RoundingStudy
  rounding_study(const Parameters::ScenarioParameters &scene,
                 const CornerAnalysis                 &own,
                 const Output::ResultFolder           &folder,
                 const std::function<double()>        &seconds_left,
                 const Progress                       &progress)
  {
    RoundingStudy study;
    const double  tolerance = scene.corner.converged_change;
    for (const double radius : scene.corner.rounding_radii)
      {
        if (radius == scene.geometry.corner_rounding_radius)
          {
            study.points.push_back(
              rounding_point(radius, own.levels, tolerance));
            continue;
          }
        // The far field stays the scene's: its global refinements are
        // kept (auto would refine everything for a small radius: 371k DoFs
        // at 2 mm on the default scene), the zoom resolves the corner.
        Parameters::ScenarioParameters rounded  = scene;
        rounded.geometry.corner_rounding_radius = radius;
        rounded.mesh.global_refinements = Scene::global_refinements(scene);
        const Corner::CornerSite site =
          Corner::floor_corner_site(rounded, scene.corner.joint);
        CornerZoom                 zoom(rounded, site);
        const Output::ResultFolder radius_folder(
          folder.path_of(fmt::format("radius_{:.4g}_m", radius)));
        bool started = false;
        for (unsigned int level = 0; level <= scene.corner.max_zoom_levels;
             ++level)
          {
            const auto  &done = zoom.levels();
            const double needed =
              done.empty() ?
                (own.levels.empty() ? 0. : own.levels[0].wall_time) :
                2. * done.back().wall_time;
            if (seconds_left() < needed)
              break;
            started = true;
            if (!zoom.next(Output::ResultFolder(
                  radius_folder.path_of("level_" + std::to_string(level)))))
              break;
            const auto &levels = zoom.levels();
            progress(fmt::format("radius {:.4g} m, level {:2d}: peak {:.4e} Pa",
                                 radius,
                                 level,
                                 levels.back().profile.peak_traction));
            if (rounding_point(radius, levels, tolerance).converged)
              break;
          }
        if (started)
          study.points.push_back(
            rounding_point(radius, zoom.levels(), tolerance));
      }

    std::vector<double> radii, peaks;
    study.falls_with_radius      = true;
    const RoundingPoint *smaller = nullptr;
    for (const auto &point : study.points)
      if (point.converged)
        {
          radii.push_back(point.radius);
          peaks.push_back(point.peak);
          if (smaller && !(point.peak < smaller->peak))
            study.falls_with_radius = false;
          smaller = &point;
        }
    study.fitted_power = radii.size() >= 2 ? log_log_slope(radii, peaks) : 0.;
    if (radii.size() < 2)
      study.falls_with_radius = false;
    return study;
  }
} // namespace FloorBlock::Studies
