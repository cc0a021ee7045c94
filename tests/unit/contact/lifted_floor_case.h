#pragma once

#include <contact/contact_problem.h>
#include <contact/contact_solver.h>

namespace FloorBlock::Testing
{
  /** @brief A level block assembly lifted into y = x^2/k (the UDEC loading path). */
  struct LiftedFloorCase
  {
    unsigned int n_blocks = 6;
    /** Corner rounding length r (m); 0 = sharp. */
    double rounding = 0.;
    /** Cell size at the contact corners (m). */
    double                corner_size = 0.05;
    Contact::JointLawKind law         = Contact::JointLawKind::compliant;
    /** 650 t of support load on blocks 1-3 (needs n_blocks >= 3). */
    bool support_load = true;
    /** Window of the averaged peak normal stress (m). */
    double averaging_length = 0.1;
    /** ContactSolverSettings::extrapolate_increments. */
    bool extrapolate_increments = true;
  };

  /** @brief Converged end state of a LiftedFloorCase and its size. */
  struct LiftedFloorOutcome
  {
    Contact::IncrementResult last;
    unsigned int             n_cells = 0;
    unsigned int             n_pairs = 0;
    /** Newton iterations of all converged increments. */
    unsigned int n_newton_iterations = 0;
  };

  /**
   * @brief Meshes and solves a LiftedFloorCase: gravity, support pressure,
   * then the base lifted into u_y = x^2/400 (lift 0.09 m at x = 6 m).
   * Joints: Table 6.1 stiffnesses (compliant) or the rigid law, friction
   * 35 deg vertical, 25 deg bedding, no cohesion or tensile strength.
   */
  LiftedFloorOutcome
  run_lifted_floor(const LiftedFloorCase &floor_case);
} // namespace FloorBlock::Testing
