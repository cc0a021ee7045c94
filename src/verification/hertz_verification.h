#pragma once

#include <contact/contact_problem.h>

#include <cmath>
#include <vector>

namespace FloorBlock::Verification
{
  /** @brief Plain settings of the Hertz line-contact verification. */
  struct HertzSettings
  {
    double radius         = 1.;     ///< radius R of the contact (m)
    double line_load      = 2.0e7;  ///< load per unit length P (N/m)
    double youngs_modulus = 1.0e10; ///< E of the elastic body (Pa)
    double poissons_ratio = 0.3;    ///< nu of the elastic body (-)
    /**
     * Contact cell size a / N with a the closed-form half-width: the mesh
     * is sized from the answer it checks (graded away from the contact
     * zone), so every radius, load and modulus gets the same resolution.
     */
    unsigned int          cells_per_half_width = 32;
    Contact::JointLawKind law                  = Contact::JointLawKind::rigid;
    /** Stiffness of the compliant law (Pa/m), ignored for rigid. */
    double       compliant_stiffness = 1e14;
    unsigned int fe_degree           = 1;
  };

  /**
   * Relative tolerance of the computed half-width (the joint report's
   * closed length). Measured at 32 cells per half-width, rigid law: 0.02
   * to 0.25 % for a/R from 0.001 to 0.1 (src/verification/README.md).
   */
  constexpr double hertz_half_width_tolerance = 0.005;
  /**
   * Relative tolerance of the peak pressure against Hertz's p0. With the
   * elastic half-space block of run_hertz_verification() the computed
   * problem is Hertz's own (flat surface, parabolic gap), so no model
   * error is allowed for. The quarter disc used until 2026-11-25 differed
   * from Hertz's theory by about -0.23 (a/R)^2 (-0.22 % at a/R = 0.1).
   */
  constexpr double hertz_peak_pressure_tolerance = 0.001;
  /**
   * Size of the elastic block, in closed-form half-widths a: W = 300 a
   * wide (half model) and deep. A finite body's compliance differs from
   * the half-space's by terms of order (a/W)^2; its stresses, from the top
   * load and the finite size, by order p0 a/W: at W = 100 a that was 1.8 %
   * of sigma_z at depth 2a, at 300 a it is 0.2 %.
   */
  constexpr double hertz_body_half_widths = 300.;

  /**
   * Tolerance of sigma_x and sigma_z on the axis at depths a and 2a
   * against Johnson's eq. 4.75, relative to |sigma_z| there (the larger
   * principal stress): the stress of the FE field, read at a distance from
   * the contact as the critical-distance methods read it. Relative to
   * |sigma_z| because a strength factor takes both principal stresses, so
   * an error in the smaller one counts by its size against the larger; and
   * sigma_x at 2a, only p0/40, carries the finite block's own stress of
   * order p0 a/W (+1.9 % of itself at 64 cells per a, 0.05 % of sigma_z).
   */
  constexpr double hertz_axis_stress_tolerance = 0.01;

  /** @brief The stresses on the axis at one depth (Pa, compression
   * negative). */
  struct HertzAxisCheck
  {
    double depth            = 0.; ///< m below the contact's centre
    double sigma_x_exact    = 0.; ///< Analytic::hertz_axis_stress()
    double sigma_z_exact    = 0.;
    double sigma_x_computed = 0.; ///< Fem::stresses_at_points()
    double sigma_z_computed = 0.;

    /** @brief |sigma_z| of eq. 4.75, the stress scale of the checks. */
    double
    stress_scale() const
    {
      return std::abs(sigma_z_exact);
    }
  };

  /** @brief Computed versus closed-form Hertz quantities. */
  struct HertzResult
  {
    /** \f$a = \sqrt{4PR/(\pi E^*)}\f$ (m), from
     *  Analytic::hertz_line_contact(). */
    double half_width_exact = 0.;
    /** The contact joint's closed length (m), JointReport::closed_length. */
    double half_width_computed = 0.;
    /** \f$p_0 = 2P/(\pi a)\f$ (Pa), from Analytic::hertz_line_contact(). */
    double peak_pressure_exact = 0.;
    /** Largest nodal contact pressure (Pa). */
    double peak_pressure_computed = 0.;
    /** Total contact force of the half model times 2 (N/m); equals P. */
    double contact_force = 0.;
    /** Position of the last closed node (m): the discrete contact. */
    double last_closed_position = 0.;
    /** Distance between the last closed and the first open node (m). */
    double       contact_cell_size = 0.;
    unsigned int n_dofs            = 0;
    /** On the axis at depths a and 2a (closed-form a). */
    std::vector<HertzAxisCheck> axis;
    /** Newton iterations, summed over the increments. */
    unsigned int n_newton_iterations = 0;
    double
    half_width_error() const
    {
      return half_width_computed / half_width_exact - 1.;
    }
    double
    peak_pressure_error() const
    {
      return peak_pressure_computed / peak_pressure_exact - 1.;
    }
  };

  /**
   * @brief Hertz line contact of radius R, plane strain, frictionless
   * (Johnson, Contact Mechanics, 1985, eq. 4.43 and 4.45 with a rigid
   * counterpart: \f$E^* = E/(1-\nu^2)\f$).
   *
   * Model: Hertz's own problem. An elastic block standing for the
   * half-space (half model [0, W] x [0, W], W = hertz_body_half_widths a,
   * symmetric about x = 0, the load P/2 as a uniform pressure on its top)
   * pressed on a rigid parabolic obstacle of curvature 1/R
   * (JointDefinition::obstacle_curvature: initial gap x^2 / (2R), the
   * normal vertical); mesh refined locally around the contact point.
   * An elastic cylinder on a rigid flat has the same Hertz solution but
   * differs from it by about -0.23 (a/R)^2 in the peak (its surface is a
   * circle, not a parabola, and curved). Throws
   * Contact::ContactSolveFailure if it does not converge.
   */
  HertzResult
  run_hertz_verification(const HertzSettings &settings);
} // namespace FloorBlock::Verification
