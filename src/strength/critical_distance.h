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
} // namespace FloorBlock::Strength
