#pragma once

#include <cstddef>
#include <vector>

namespace FloorBlock::Analytic
{
  /**
   * @brief Bedding inclinations alpha_i (rad) under a chain of n blocks of
   * width L on the parabolic bedding \f$y = x^2/k\f$, x measured from the
   * face (positive away from it), block n against the face.
   *
   * Block i spans \f$x \in [(n-i)L, (n-i+1)L]\f$; its base chord has slope
   * \f$(2(n-i)+1)L/k\f$, which for a parabola equals the tangent slope at
   * the block centre, so \f$\alpha_i = \arctan((2(n-i)+1)L/k)\f$.
   * Returned in chain order (index 0 = block 1, the farthest).
   *
   * @param[in] n_blocks n >= 1.
   * @param[in] block_width L (m), > 0.
   * @param[in] curvature_length k (m), > 0 (the chapter's 400, 200, 100, 50).
   * @throw FloorBlock::InputError for n = 0 or non-positive L or k.
   */
  std::vector<double>
  parabolic_inclinations(const std::size_t n_blocks,
                         const double      block_width,
                         const double      curvature_length);

  /**
   * @brief Rise of a parabolic bedding \f$y = x^2/k\f$ from the face to the
   * free end of the chain, \f$(nL)^2/k\f$ (m): the sum of
   * \f$L\tan\alpha_i\f$ over the chord inclinations of
   * parabolic_inclinations(), the floor the closed forms stand the blocks
   * on. The FEM's parabolic uplift reaches this height at x = nL when it
   * lifts a flat bedding into that floor.
   * @param[in] n_blocks n >= 1.
   * @param[in] block_width L (m), > 0.
   * @param[in] curvature_length k (m), > 0.
   * @throw FloorBlock::InputError for n = 0 or non-positive L or k.
   */
  double
  parabolic_bedding_rise(const std::size_t n_blocks,
                         const double      block_width,
                         const double      curvature_length);

  /**
   * @brief Rise of a planar bedding of inclination alpha from the face to
   * the free end of the chain, \f$nL\tan\alpha\f$ (m), negative where the
   * bed falls away from the face: the sum of \f$L\tan\alpha\f$ over the
   * n blocks the closed forms stand on it.
   * @param[in] n_blocks n >= 1.
   * @param[in] block_width L (m), > 0.
   * @param[in] inclination alpha (rad), |alpha| < pi/2.
   * @throw FloorBlock::InputError for n = 0, non-positive L or |alpha| >=
   * pi/2.
   */
  double
  planar_bedding_rise(const std::size_t n_blocks,
                      const double      block_width,
                      const double      inclination);

  /**
   * @brief Floor lift y of eq. 6.51 at a joint: the differential lift
   * across one block width produced by the relative rotation of the two
   * joint faces, \f$y = L\tan(\alpha_{away} - \alpha_{face})\f$.
   *
   * For the joint against the fixed (upright) face block use
   * inclination_face_side = 0; on the parabola that gives \f$y = L^2/k\f$,
   * the floor elevation at x = L. For a planar bed it gives
   * \f$y = L\tan\alpha\f$ at the face and 0 at inner joints.
   *
   * @param[in] inclination_away_side alpha of the block farther from the
   * face (rad).
   * @param[in] inclination_face_side alpha of the block nearer the face, 0
   * for the face block (rad).
   * @param[in] block_width L (m).
   * @return y (m); zero or negative means the joint does not close at the
   * top, which corner_contact() reports as zero_floor_lift.
   * @throw FloorBlock::InputError for L <= 0 or a non-finite relative
   * rotation, or one of 90 degrees or more.
   */
  double
  joint_floor_lift(const double inclination_away_side,
                   const double inclination_face_side,
                   const double block_width);

  /**
   * @brief Young's modulus from bulk and shear modulus,
   * \f$E = 9KG/(3K+G)\f$ (Pa).
   * @throw FloorBlock::InputError unless K > 0 and G > 0.
   */
  double
  youngs_modulus_from_bulk_shear(const double bulk_modulus,
                                 const double shear_modulus);

  /**
   * @brief Poisson's ratio from bulk and shear modulus,
   * \f$\nu = (3K - 2G)/(2(3K+G))\f$ (dimensionless).
   * @throw FloorBlock::InputError unless K > 0 and G > 0.
   */
  double
  poisson_ratio_from_bulk_shear(const double bulk_modulus,
                                const double shear_modulus);
} // namespace FloorBlock::Analytic
