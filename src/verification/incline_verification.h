#pragma once

#include <contact/contact_problem.h>
#include <contact/results.h>
#include <verification/verification_setup.h>

#include <optional>

namespace FloorBlock::Verification
{
  /** @brief Settings of the block-on-an-incline verification. */
  struct InclineSettings
  {
    double friction_angle = 30. * M_PI / 180.; ///< phi of the joint (rad)
    /** Incline alpha (rad); the block slips iff tan(alpha) > tan(phi). */
    double                incline          = 0.;
    double                normal_stiffness = 9e9;   ///< kn, Table 6.1 (Pa/m)
    double                shear_stiffness  = 6.7e9; ///< ks, Table 6.1 (Pa/m)
    Contact::JointLawKind law              = Contact::JointLawKind::compliant;
  };

  /** @brief Outcome of the incline case: stuck with forces, or slipping. */
  struct InclineResult
  {
    double weight = 0.; ///< W of the block per metre (N/m)
    /** Quasi-statics has no equilibrium for a sliding block: the solver
     *  failing with every closed pair at the slip limit means "slips". */
    bool slipped = false;
    /** Stuck: the converged increment (joint 0 = the bedding). */
    std::optional<Contact::IncrementResult> stuck;
    /** Slipped: counts of the last Newton iterate, attempts, and whether
     *  any increment had converged before the failure. */
    Contact::StateCounts last_iterate_counts;
    unsigned int         n_failed_attempts   = 0;
    bool                 had_converged_state = false;
  };

  /**
   * Relative tolerance of the stuck block's joint shear and normal force:
   * they balance the block's weight, which holds exactly in any
   * discretisation, so only round-off and the Newton tolerance remain.
   */
  constexpr double incline_tolerance = equilibrium_tolerance;

  /**
   * @brief The case's verdict "the block slips": no equilibrium was found
   * from the start, and the last Newton iterate had closed pairs, every
   * one of them at the slip limit (none stuck).
   */
  bool
  slips(const InclineResult &result);

  /**
   * @brief Block (1 m x 0.5 m, 2500 kg/m^3, table rock) resting on an
   * elastic base over a Coulomb joint, gravity tilted by the incline
   * alpha (the same problem as tilting the geometry, without a rotated
   * mesh). Closed form: the block stays iff tan(alpha) <= tan(phi), and a
   * stuck block's joint carries shear W sin(alpha) and normal force
   * W cos(alpha).
   */
  InclineResult
  run_incline_verification(const InclineSettings &settings);
} // namespace FloorBlock::Verification
