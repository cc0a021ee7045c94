#pragma once

#include <rigid/model.h>

namespace FloorBlock::RigidBlocks::Testing
{
  /** Chapter Table 6.1: kn = 9 GPa/m (Pa/m). */
  constexpr double table_normal_stiffness = 9e9;
  /** Chapter Table 6.1: ks = 6.7 GPa/m (Pa/m). */
  constexpr double table_shear_stiffness = 6.7e9;
  /** Rock density of the UDEC scene (kg/m^3). */
  constexpr double rock_density = 2500.;
  /** Standard gravity (m/s^2). */
  constexpr double standard_gravity = 9.80665;

  /** @brief Degrees to radians. */
  double
  radians(const double degrees);

  /** @brief Table 6.1 joint (no cohesion, no tension) with friction angle phi (rad). */
  Contact::JointConstants
  table_joint(const double friction_angle);

  /**
   * @brief n blocks (L = 1 m, H = 2 m) on a planar bedding of inclination
   * alpha (rad, rising away from the face), Table 6.1 joints, gravity only,
   * one increment per stage, no uplift.
   */
  ModelDescription
  planar_scene(const unsigned int n_blocks,
               const double       inclination,
               const double       bedding_friction,
               const double       vertical_friction);

  /**
   * @brief The default scene: 6 blocks on the parabola y = x^2/400,
   * phi_h = phi_v = 30 deg, 650 t shared by chapter blocks 1-3 over a
   * support width of 1.5 m, then the bedding lifted by 0.05 m (vertical
   * translation) in @p n_uplift increments.
   */
  ModelDescription
  default_scene(const unsigned int n_uplift);

  /**
   * @brief The default scene read as a lifted flat bedding: the blocks stand
   * on a flat base that is bent into y = x^2/400 (UpliftMotion::parabola,
   * vertex at the face) in @p n_uplift increments.
   */
  ModelDescription
  lifted_parabola_scene(const unsigned int n_uplift);

  /** @brief The report of joint @p number of @p kind in @p increment. */
  const RigidJointReport &
  find_joint(const IncrementReport &increment,
             const JointKind        kind,
             const unsigned int     number);
} // namespace FloorBlock::RigidBlocks::Testing
