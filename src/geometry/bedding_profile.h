#pragma once

#include <geometry/assembly_description.h>

namespace FloorBlock::Geometry
{
  /**
   * @brief Height of the bedding joint as a function of the distance x from
   * the face: planar y = x tan(alpha), or parabolic y = x^2/k (chapter
   * section 6.6.2, x measured from the face).
   *
   * Under the face block (x < 0) the parabola is continued by its tangent
   * at x = 0, the horizontal line y = 0, instead of rising again as x^2/k
   * would: the face block is fixed and only needs a seat, and the tangent
   * continuation keeps the bedding smooth (C1) at the face. The planar
   * bedding simply continues its line.
   *
   * Every piece of the profile on one side of x = 0 is a polynomial of
   * degree <= 2, so a piece between x_a and x_b is exactly the quadratic
   * Bezier curve with control points (x_a, y(x_a)),
   * ((x_a + x_b)/2, y(x_a) + y'(x_a) (x_b - x_a)/2), (x_b, y(x_b)).
   */
  class BeddingProfile
  {
  public:
    /**
     * @brief The profile of the mesh: flat when the scene reads floor
     * uplift as a lifted flat bedding, otherwise the inclined bedding.
     */
    static BeddingProfile
    geometry_profile(const AssemblyDescription &description);

    /**
     * @brief The planar or parabolic profile itself, whatever the reading:
     * for FloorUplift::lifted_flat_bedding this is the vertical uplift the
     * solver prescribes along the bedding (up to its load factor).
     */
    static BeddingProfile
    uplift_profile(const AssemblyDescription &description);

    /** @brief Height y(x) of the bedding. Units: m. @param[in] x Distance from the face, m. */
    double
    height(const double x) const;

    /** @brief Slope dy/dx of the bedding at x. Units: 1. */
    double
    slope(const double x) const;

    /** @brief Second derivative d2y/dx2 at x. Units: 1/m. */
    double
    second_derivative(const double x) const;

    /**
     * @brief Exact integral of y(x) from x_a to x_b (both on the same side of
     * x = 0). Units: m^2.
     */
    double
    integral(const double x_a, const double x_b) const;

    /**
     * @brief Middle control point height of the quadratic Bezier that equals
     * the profile (shifted by @p shift) between x_a and x_b. Always computed
     * from the smaller x so that the two sides of a joint get bit-identical
     * control points. Units: m.
     */
    double
    bezier_control_height(const double x_a,
                          const double x_b,
                          const double shift) const;

    /** @brief Whether the profile is a straight line between x_a and x_b. */
    bool
    is_straight(const double x_a, const double x_b) const;

  private:
    BeddingProfile(const BeddingShape shape,
                   const double       slope_of_plane,
                   const double       curvature);

    BeddingShape shape;
    /** tan(alpha) of the planar bedding. Units: 1. */
    double slope_of_plane;
    /** k of y = x^2/k. Units: m. */
    double curvature;
  };
} // namespace FloorBlock::Geometry
