#pragma once

#include <contact/contact_problem.h>

namespace FloorBlock::Verification
{
  /** @brief Plain settings of the Hertz line-contact verification. */
  struct HertzSettings
  {
    double radius         = 1.;     ///< cylinder radius R (m)
    double line_load      = 2.0e7;  ///< load per unit length P (N/m)
    double youngs_modulus = 1.0e10; ///< E of the cylinder (Pa)
    double poissons_ratio = 0.3;    ///< nu of the cylinder (-)
    /** Local refinements towards the contact point (each halves h there). */
    unsigned int          mesh_level = 6;
    Contact::JointLawKind law        = Contact::JointLawKind::rigid;
    /** Stiffness of the compliant law (Pa/m), ignored for rigid. */
    double       compliant_stiffness = 1e14;
    unsigned int fe_degree           = 1;
  };

  /**
   * Relative tolerance of the computed half-width: the contact edge is
   * resolved only to one contact cell (measured 1.25 % at the default
   * mesh level 6, rigid law: tests/benchmark/RESULTS.md).
   */
  constexpr double hertz_half_width_tolerance = 0.02;
  /**
   * Relative tolerance of the peak pressure: a nodal value of a smooth
   * field (measured 0.25 % at mesh level 6, rigid law).
   */
  constexpr double hertz_peak_pressure_tolerance = 0.05;

  /** @brief Computed versus closed-form Hertz quantities. */
  struct HertzResult
  {
    /** \f$a = \sqrt{4PR/(\pi E^*)}\f$ (m), from
     *  Analytic::hertz_line_contact(). */
    double half_width_exact = 0.;
    /** Midway between the last closed and the first open node (m). */
    double half_width_computed = 0.;
    /** \f$p_0 = 2P/(\pi a)\f$ (Pa), from Analytic::hertz_line_contact(). */
    double peak_pressure_exact = 0.;
    /** Largest nodal contact pressure (Pa). */
    double peak_pressure_computed = 0.;
    /** Total contact force of the half model times 2 (N/m); equals P. */
    double contact_force = 0.;
    /** Contact element size at the contact point (m). */
    double contact_cell_size = 0.;
    unsigned int n_dofs = 0;
    /** Newton iterations, summed over the increments. */
    unsigned int n_newton_iterations = 0;
    double       half_width_error() const
    {
      return half_width_computed / half_width_exact - 1.;
    }
    double peak_pressure_error() const
    {
      return peak_pressure_computed / peak_pressure_exact - 1.;
    }
  };

  /**
   * @brief Elastic cylinder pressed on a rigid flat, plane strain,
   * frictionless (Johnson, Contact Mechanics, 1985, eq. 4.43 and 4.45 with
   * a rigid counterpart: \f$E^* = E/(1-\nu^2)\f$).
   *
   * Model: the quarter disc below the centre, symmetric about x = 0, the
   * load P/2 applied as a uniform pressure on the horizontal cut through
   * the centre; node-to-rigid-plane contact; mesh refined locally around
   * the contact point. Throws Contact::ContactSolveFailure if it does not
   * converge.
   */
  HertzResult
  run_hertz_verification(const HertzSettings &settings);
} // namespace FloorBlock::Verification
