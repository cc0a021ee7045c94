#pragma once

#include <analytic/corner_eigenproblem.h>
#include <contact/contact_problem.h>

namespace FloorBlock::Verification
{
  /** @brief Settings of the punch verification. */
  struct PunchSettings
  {
    double pressure = 2e6; ///< on the block top (Pa)
    /**
     * Halvings of the cells around the block corner: the finest cells
     * there are 0.25 m / 2^n (n = 12: 61 um).
     */
    unsigned int corner_refinements = 12;
    double       youngs_modulus     = 16.09e9; ///< Pa (Table 6.1 rock)
    double       poissons_ratio     = 0.2;     ///< -
  };

  /**
   * Largest accepted |fitted - theory| of the corner exponent lambda
   * (0.03).
   */
  constexpr double punch_exponent_tolerance = 0.03;

  /** @brief One interface state of the punch case. */
  struct PunchCase
  {
    Analytic::InterfaceState state = Analytic::InterfaceState::stuck;
    /** Williams exponent of the corner (corner_modes(), lowest mode). */
    double theory_exponent = 0.;
    /** The next mode's exponent: the second term of the fit. */
    double second_theory_exponent = 0.;
    /**
     * lambda1 of the two-term fit K1 r^(lambda1 - 1) + K2 r^(lambda2 - 1)
     * to the interface pressure, lambda2 = second_theory_exponent
     * (Analytic::two_term_fit()).
     */
    double fitted_exponent = 0.;
    /** 1 + the slope of log p against log r (one-term fit), for comparison. */
    double one_term_exponent = 0.;
    /** K2 / K1 of the two-term fit (m^(lambda1 - lambda2)). */
    double second_over_first = 0.;
    /** Distance within which the first term alone is within 10 % (m). */
    double one_term_validity = 0.;
    double fit_from = 0.; ///< smallest distance from the corner fitted (m)
    double fit_to   = 0.; ///< largest (m)
    unsigned int n_fit_points = 0;
    /** Root-mean-square relative residual of the two-term fit (-). */
    double       fit_residual  = 0.;
    double       smallest_cell = 0.; ///< m, at the corner
    unsigned int n_dofs        = 0;
  };

  /**
   * @brief A square-ended block (half model: 1 m wide, 2 m high) pressed
   * by a uniform pressure onto an elastically similar base (3 m x 3 m,
   * standing for the half-plane), exact contact, the interface stuck
   * (friction coefficient 10, far above the 0.54 the lowest stuck mode
   * needs) or frictionless. The interface pressure near the block corner
   * is K1 r^(lambda1 - 1) + K2 r^(lambda2 - 1) + ...; lambda1 is fitted
   * (two terms, lambda2 from the eigen-solver) on the nodes between
   * punch_fit_from_cells smallest cells and punch_fit_to of the corner and
   * compared with the eigen-solver's lowest exponent
   * (Analytic::corner_modes()).
   */
  PunchCase
  run_punch_case(const PunchSettings           &settings,
                 const Analytic::InterfaceState state);

  /**
   * Fit range, inner end, in smallest cells from the corner: the nodal
   * tractions of the first cells carry the discretisation error of the
   * singularity itself.
   */
  constexpr double punch_fit_from_cells = 8.;
  /** Fit range, outer end (m): 3 % of the block's half-width. */
  constexpr double punch_fit_to = 0.03;
} // namespace FloorBlock::Verification
