#pragma once

#include <analytic/corner_eigenproblem.h>
#include <corner/corner_profile.h>

#include <string>
#include <vector>

namespace FloorBlock::Corner
{
  /** @brief Material and friction of the two bodies at the corner. */
  struct CornerMaterials
  {
    Analytic::WedgeMaterial rock; ///< both blocks (elastically similar)
    double                  friction_coefficient =
      0.; ///< tan of the vertical joints' friction angle
    /**
     * Exact (unilateral) contact, Joints/Law = rigid. The compliant law's
     * springs (kn) put a layer of compliance into the interface, which the
     * wedge eigenproblem does not have: the field is smoothed over about
     * E/kn and not asymptotic at the resolved distances.
     */
    bool   exact_contact    = true;
    double compliant_length = 0.; ///< E / kn (m), compliant law only
  };

  /**
   * @brief What the asymptotic analysis of complete and incomplete contacts
   * says about the traction at the end of a corner's contact zone.
   *
   * The traction near the end is a sum of terms K d^(lambda - 1), the
   * lambda from the eigenproblem of the two wedges meeting there
   * (Analytic::corner_modes()):
   *  - edge_in_fillet: both surfaces are smooth and curve apart, so
   *    locally two half-planes (angles pi, pi) whose interface is closed on
   *    one side and open beyond the edge. Exponents 1/2, 1, 3/2, 2, ... for
   *    similar materials in every interface state. A smooth incomplete
   *    contact has a traction that is bounded and falls to zero at the edge
   *    (both gap and pressure non-negative on either side; Johnson,
   *    Contact Mechanics, 1985, ch. 5; Barber's bounded-edge condition):
   *    that removes every mode with Re lambda <= 1, leaving the lowest
   *    lambda > 1 (3/2: t ~ d^(1/2), the Hertzian square root).
   *  - reaches_corner: a sharp block corner (pi/2) on the other block's
   *    corner (pi/2, flush) -- the blocks' tops level at the joint, as the
   *    reference geometry has them. The lowest mode is the exponent.
   *  - open_at_corner: the corner carries no traction; nothing to fit.
   * With compliant joints no case is covered (CornerMaterials::exact_contact).
   */
  struct CornerTheory
  {
    std::string         configuration;   ///< one sentence for the report
    bool                covered = false; ///< whether a fit is meaningful
    std::string         why_not;         ///< when not covered
    Analytic::WedgePair pair;
    std::vector<Analytic::CornerMode> modes;
    /** lambda of the leading term of the traction, t ~ d^(lambda - 1). */
    double exponent = 0.;
    /** lambda of the next term (the fits' second term). */
    double next_exponent = 0.;
    /** lambda of the term after it (the expansion fit's third term; 0 if none).
     */
    double third_exponent = 0.;
  };

  /**
   * @brief The theory for the state @p profile shows at a corner rounded
   * with @p rounding_radius (m, 0: sharp).
   */
  CornerTheory
  corner_theory(const CornerProfile   &profile,
                const CornerMaterials &materials,
                double                 rounding_radius);

  /** @brief "stuck", "frictionless", "slipping". */
  const char *
  to_string(Analytic::InterfaceState state);
} // namespace FloorBlock::Corner
