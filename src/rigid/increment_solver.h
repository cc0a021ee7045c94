#pragma once

#include <contact/newton_driver.h>
#include <loading/load_factors.h>
#include <rigid/block_loads.h>
#include <rigid/joint_set.h>
#include <rigid/results.h>

#include <string>
#include <vector>

namespace FloorBlock::RigidBlocks
{
  /** @brief Outcome of one load state. */
  struct IncrementOutcome
  {
    Contact::NewtonReport newton;
    /** Motions and responses of the last iterate (converged or not). */
    std::vector<BlockMotion> motions;
    JointResponses           responses;
    /** Meaningful when !newton.converged. */
    SolveStatus  failure       = SolveStatus::not_converged;
    unsigned int failing_block = 0;
  };

  /**
   * @brief Semi-smooth Newton (Contact::solve_newton, with its line search
   * and cycling guard) for the block motions at one load state, starting
   * from the last converged motions and histories.
   *
   * The residual norm counts moment rows divided by L, so that all rows
   * are forces (N/m). Before each linear solve, a block whose joint points
   * are all open is reported as SolveStatus::floating_block instead of
   * being handed to the LU. A zero pivot with closed joints (the closed
   * points slip and nothing resists the motion) is retried with the slip
   * stabilisation of RigidSolverSettings, which changes the search
   * direction only; if Newton then fails and the consistent tangent of its
   * last step was singular, the outcome is SolveStatus::no_equilibrium.
   * The residual is never regularised, so a converged answer is the
   * unmodified one.
   */
  IncrementOutcome
  solve_load_state(const JointSet                 &joint_set,
                   const std::vector<BlockLoads>  &loads,
                   const RigidSolverSettings      &settings,
                   const double                    block_width,
                   const Loading::LoadFactors     &factors,
                   const std::vector<BlockMotion> &start_motions,
                   const JointHistories           &histories);
} // namespace FloorBlock::RigidBlocks
