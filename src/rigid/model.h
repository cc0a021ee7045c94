#pragma once

#include <rigid/block_loads.h>
#include <rigid/increment_solver.h>
#include <rigid/joint_set.h>
#include <rigid/model_description.h>
#include <rigid/results.h>

#include <vector>

namespace FloorBlock::RigidBlocks
{
  /**
   * @brief Rigid blocks (3 DOF each: centroid translation and rotation,
   * small rotations) on compliant Coulomb joints integrated along every
   * joint, loaded in the FE model's stages: gravity, support loads, then
   * the prescribed base uplift, each in increments with cutback.
   *
   * The face block is fixed; the base is rigid and follows
   * Contact::uplift_displacement() (translation, tilt, or the parabola
   * bending evaluated at each joint point).
   *
   * The stages run on Loading::follow_load_path, as in
   * Contact::ContactSolver: a stage with 0 increments is skipped, and
   * later stages apply the earlier loads at full factor (so a skipped
   * gravity stage means gravity enters with the first support-load
   * increment). Gravity always has its own stage here
   * (LoadSteps::gravity_with_pressure is not followed).
   */
  class Model
  {
  public:
    /** @throws InputError for an invalid description (validate()). */
    explicit Model(const ModelDescription &description);

    /**
     * @brief Run the whole loading path.
     * @return Converged increments with joint tables and block motions;
     * on failure the increments reached so far, a status and a message
     * (never NaN/inf values).
     */
    RigidSolveResult
    solve() const;

    /**
     * @brief Joint reports for prescribed block motions, from fresh (virgin)
     * joint histories, without solving for equilibrium. Used to check the
     * joint integration on its own (e.g. the Winkler reading of Eq. 6.51).
     * @param[in] motions One motion per block, index i - 1.
     * @param[in] uplift_factor Fraction of the prescribed base uplift (-).
     */
    std::vector<RigidJointReport>
    evaluate_prescribed(const std::vector<BlockMotion> &motions,
                        const double                    uplift_factor) const;

    const JointSet &
    joint_set() const;

    /** Loads of every block at full factor, index i - 1. */
    const std::vector<BlockLoads> &
    loads() const;

  private:
    const ModelDescription        description;
    const JointSet                joints;
    const std::vector<BlockLoads> block_load_list;
  };
} // namespace FloorBlock::RigidBlocks
