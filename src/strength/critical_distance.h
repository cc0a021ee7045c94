#pragma once

#include <strength/strength_factor.h>

#include <vector>

namespace FloorBlock::Strength
{
  /**
   * @brief The material length of the theory of critical distances
   * (Taylor, "The theory of critical distances", Elsevier 2007, eq. 2.6):
   * \f$L = \frac{1}{\pi}\left(\frac{K_{Ic}}{\sigma_t}\right)^2\f$ (m).
   * @param[in] fracture_toughness K_Ic (Pa m^0.5), > 0.
   * @param[in] tensile_strength sigma_t (Pa), > 0.
   */
  double
  critical_distance(double fracture_toughness, double tensile_strength);

  /** @brief The stress at a distance along a path from a hot spot. */
  struct PathSample
  {
    double            distance = 0.; ///< m from the hot spot, increasing
    PlaneStrainStress stress;
  };

  /**
   * @brief The point method: the stress at L/2 from the hot spot, linear
   * between the samples around it (Taylor 2007, section 2.3).
   * @param[in] path Samples in increasing distance, the first at 0 and
   *   the last at L/2 or beyond. Throws std::invalid_argument otherwise.
   */
  PlaneStrainStress
  point_method_stress(const std::vector<PathSample> &path, double length);

  /**
   * @brief The line method: the mean stress over the distances 0 to L,
   * the integral of the linear interpolant of the samples (exact for a
   * field linear between them) over L.
   * @param[in] path Samples in increasing distance, the first at 0 and
   *   the last at L or beyond. Throws std::invalid_argument otherwise.
   */
  PlaneStrainStress
  line_method_stress(const std::vector<PathSample> &path, double length);

  /**
   * @brief The area method: the mean stress over the material within L of
   * the hot spot, a sector read along rays from it at equal angles (each
   * ray's angle the middle of its share of the sector). Each ray
   * contributes the integral over [0, L] of the linear interpolant of its
   * samples weighted by the radius, $rac{2}{L^2}\int_0^L\sigmaho\,
   * dho$, and the rays are averaged (the midpoint rule in angle).
   *
   * Why beside the point and line methods: by equilibrium the mean stress
   * over a region is set by the tractions on its boundary alone,
   * $\int_A\sigma\,dA = \oint \mathrm{sym}(t\otimes x)\,ds$; here the
   * free surface (none), the joint face (the contact tractions within L
   * and their first moment) and the arc at L. How the contact pressure is
   * spread within a few rounding radii of the corner moves that first
   * moment by a fraction of r/L, where it moves the stress state at one
   * point near the corner by a large fraction.
   * @param[in] rays Each as for line_method_stress(): samples in
   *   increasing distance from 0 to at least L. Throws
   *   std::invalid_argument if empty or if a ray is not such a path.
   */
  PlaneStrainStress
  area_method_stress(const std::vector<std::vector<PathSample>> &rays,
                     double                                      length);
} // namespace FloorBlock::Strength
