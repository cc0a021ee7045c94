#pragma once

#include <geometry/assembly_description.h>
#include <geometry/body_outline.h>

#include <vector>

namespace FloorBlock::Geometry
{
  /**
   * @brief A requested cell size at one point, from a solution-driven
   * refinement indicator (`floorblock converge`).
   *
   * Two consumers: `--mode remesh` re-meshes with Gmsh through
   * add_local_size_field() (a size field is global and the joint sides stay
   * periodic copies of each other, so both sides of every joint get the
   * same new nodes); `--mode adaptive` flags the deal.II cells the requests
   * touch (Refinement::refine_matched, which keeps the joint sides
   * matched itself).
   */
  struct LocalSize
  {
    Point2 position; ///< m
    double size;     ///< requested cell size at position (m)
  };

  /**
   * @brief Refuses local sizes that are not finite and positive or are
   * below min_relative_local_size times the smaller block side, so a
   * run-away indicator cannot ask for millions of cells.
   * @throws FloorBlock::InputError naming the point and the size.
   */
  void
  validate_local_sizes(const std::vector<LocalSize> &local_sizes,
                       const AssemblyDescription    &description);

  /**
   * @brief The size request @p local asks for at @p distance (m) from its
   * point: h_p + (g - 1) d, the grading law of the corner refinement of
   * write_gmsh_mesh() (g = @p growth_rate). Units: m.
   */
  double
  graded_size(const LocalSize &local,
              const double     growth_rate,
              const double     distance);

  /**
   * @brief The graded size the points ask for at @p point:
   * \f$h(x) = \min_p (h_p + (g - 1)\,|x - x_p|)\f$, the same grading law as
   * the corner refinement of write_gmsh_mesh() (g = growth rate).
   * Units: m; a very large number when @p local_sizes is empty.
   */
  double
  local_size_at(const std::vector<LocalSize> &local_sizes,
                const double                  growth_rate,
                const Point2                 &point);

  /**
   * @brief Size class a requested size is rounded down to: the next lower
   * power of 2^(1/4). Points of one class share one Gmsh Distance field,
   * so the number of fields stays small (a factor 1000 in size is 40
   * classes) however many points an indicator produces; rounding down
   * never coarsens a request, by at most 16 %. Units: m.
   */
  double
  local_size_class(const double size);

  /**
   * @brief Adds Gmsh fields that evaluate to
   * min(local_size_at(), @p largest_size) with the sizes rounded down to
   * their local_size_class(): per class one Distance field over the
   * class's points and a Threshold field, size + (g - 1) distance up to
   * @p largest_size (the far size: beyond it the request has no effect),
   * then the Min of all classes.
   *
   * Pre-condition: a GmshScope with the current model is open; the points
   * become OCC points that belong to no surface and no physical group.
   * @return The tag of the Min field, or -1 if @p local_sizes is empty.
   */
  int
  add_local_size_field(const std::vector<LocalSize> &local_sizes,
                       const double                  growth_rate,
                       const double                  largest_size);
} // namespace FloorBlock::Geometry
