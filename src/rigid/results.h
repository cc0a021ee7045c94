#pragma once

#include <contact/active_set.h>
#include <contact/joint_law.h>
#include <contact/results.h>
#include <rigid/block_motion.h>
#include <rigid/joint_layout.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace FloorBlock::RigidBlocks
{
  /** @brief State of one integration point, for profiles along a joint. */
  struct ProfilePoint
  {
    /** Distance along the joint (JointPoint::coordinate) (m). */
    double coordinate = 0.;
    /** Undeformed position (m). */
    dealii::Point<2> position;
    /** Normal traction, compression positive (Pa). */
    double normal_traction = 0.;
    /** Shear traction in the sense of RigidJointReport::shear_force (Pa). */
    double shear_traction = 0.;
    /** Normal gap, negative in overlap (m). */
    double              gap   = 0.;
    Contact::JointState state = Contact::JointState::open;
  };

  /**
   * @brief Integrated state of one joint (chapter numbering), per metre of
   * face.
   */
  struct RigidJointReport
  {
    std::string  name;
    JointKind    kind   = JointKind::vertical;
    unsigned int number = 0;
    /** Normal force, compression positive; Q_j of a vertical joint (N/m). */
    double normal_force = 0.;
    /**
     * Shear force (N/m), positive in the sense of the chapter's mechanism:
     * on a vertical joint the downward force on block j (the chapter's V_j,
     * Q tan phi_v at slip); on a bedding joint the force on the block along
     * the bedding towards the face (N tan phi_h at slip).
     */
    double shear_force = 0.;
    /**
     * Length of joint in compression (m); a zone ending between two points
     * is cut at the zero of the linearly interpolated overlap.
     */
    double contact_length = 0.;
    /** Largest normal traction (Pa) and its coordinate along the joint (m). */
    double peak_normal_traction = 0.;
    double peak_coordinate      = 0.;
    /** normal_force / contact_length, 0 without contact (Pa). */
    double               mean_normal_traction = 0.;
    Contact::StateCounts counts;
    /** Resultant contact force on side B (N/m) ... */
    dealii::Tensor<1, 2> force_on_side_b;
    /** ... and its moment about the origin, counter-clockwise (N m/m). */
    double moment_on_side_b = 0.;
    /** Point values; filled for the last increment only unless asked. */
    std::vector<ProfilePoint> profile;
  };

  /** @brief One converged load increment. */
  struct IncrementReport
  {
    Loading::LoadStage stage = Loading::LoadStage::gravity;
    /** Factors of gravity, support load and uplift after the increment (-). */
    double       gravity_factor = 0.;
    double       support_factor = 0.;
    double       uplift_factor  = 0.;
    unsigned int n_iterations   = 0;
    /** Halvings needed before this increment converged. */
    unsigned int n_cutbacks = 0;
    /** Final Newton residual over its reference force (-). */
    double               relative_residual = 0.;
    Contact::StateCounts counts;
    /** Joints: vertical 1..n, then bedding 1..n. */
    std::vector<RigidJointReport> joints;
    /** Block motions, index i - 1. */
    std::vector<BlockMotion> motions;
    /**
     * Largest force or moment (over L) imbalance of a block, recomputed from
     * the joint resultants and the loads, over the larger of the total
     * applied load and the largest joint resultant (-).
     */
    double relative_imbalance = 0.;
    /** Wall time of the increment (s). */
    double wall_time = 0.;
  };

  enum class SolveStatus
  {
    converged,
    /** A block had all its joints open: no contact holds it. */
    floating_block,
    /**
     * The tangent is singular while the block has closed joints: its closed
     * points slip and nothing resists the motion, so no static equilibrium
     * exists (e.g. a block on a bed steeper than its friction angle).
     */
    no_equilibrium,
    /** Newton failed (divergence, cycling) after all cutbacks. */
    not_converged
  };

  /** @brief One-word name of a status ("converged", "floating_block", ...). */
  std::string
  to_string(const SolveStatus status);

  /** @brief Everything a solve produced. */
  struct RigidSolveResult
  {
    SolveStatus status = SolveStatus::converged;
    /** Why the solve stopped early; empty when converged. */
    std::string message;
    /** Chapter number of the block named by a failure, 0 if none. */
    unsigned int failing_block = 0;
    /** Converged increments, in load order (kept on failure too). */
    std::vector<IncrementReport> increments;
    /** Every failed attempt, "stage factor (step): reason". */
    std::vector<std::string> failed_attempts;
    /** Wall time of the whole solve (s). */
    double wall_time = 0.;
  };
} // namespace FloorBlock::RigidBlocks
