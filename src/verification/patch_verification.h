#pragma once

#include <contact/contact_problem.h>
#include <contact/results.h>
#include <verification/verification_setup.h>

namespace FloorBlock::Verification
{
  /**
   * Relative tolerance of the joint force, the extreme nodal tractions and
   * the joint shear: Q1 and Q2 elements represent the uniform stress
   * exactly, so only round-off and the Newton tolerance remain.
   */
  constexpr double patch_tolerance = equilibrium_tolerance;

  /** @brief Settings of the contact patch test. */
  struct PatchSettings
  {
    double pressure = 2e6; ///< applied on the top of the upper body (Pa)
    Contact::JointLawKind    law           = Contact::JointLawKind::compliant;
    unsigned int             fe_degree     = 1;
    Solver::LinearSolverKind linear_solver = Solver::LinearSolverKind::direct;
  };

  /** @brief Solution of the patch test: the one increment and the closed form. */
  struct PatchResult
  {
    Contact::IncrementResult increment; ///< last (only) increment
    unsigned int             n_increments = 0;
    double                   joint_length = 0.; ///< m
    /** Closed form: the joint traction equals the applied pressure (Pa). */
    double applied_pressure = 0.;
  };

  /**
   * @brief Contact patch test: two unit squares (table rock, matching
   * meshes 4x3 and 4x5) pressed together over a flat horizontal joint by a
   * uniform pressure on the top, on rollers (bottom and left sides). The
   * exact solution is uniform uniaxial stress, so every joint node must
   * carry the applied pressure, the joint force is pressure x length and
   * the joint shear is zero. Throws Contact::ContactSolveFailure if it
   * does not converge.
   */
  PatchResult
  run_patch_verification(const PatchSettings &settings);
} // namespace FloorBlock::Verification
