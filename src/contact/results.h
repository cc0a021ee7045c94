#pragma once

#include <contact/active_set.h>
#include <fem/rigid_motion.h>
#include <loading/load_stage.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace FloorBlock::Contact
{
  /** @brief State of one joint node, for profiles along the joint. */
  struct JointNodeSample
  {
    /** Distance along the joint from its first node (m). */
    double           arc_position = 0.;
    dealii::Point<2> position;
    double           normal_traction = 0.; ///< Pa, compression > 0
    double     tangential_traction = 0.; ///< Pa, along the tangent (-n_y, n_x)
    double     gap                 = 0.; ///< m
    JointState state               = JointState::open;
    /** JointResponse::exact_traction of the pair. */
    bool exact_traction = false;
  };

  /**
   * @brief One cross-section of a 3D joint (make_swept_joint_reports()):
   * the joint line at one slice position z, standing for the length of
   * face between the midpoints to its neighbours (the lumped weights' own
   * share), with that line's figures per metre of face.
   */
  struct JointSection
  {
    double z                  = 0.; ///< m, the line's position along the face
    double z_from             = 0.; ///< m, start of the face it stands for
    double z_to               = 0.; ///< m, end of the face it stands for
    double normal_force       = 0.; ///< N/m, the line's normal force per metre
    double shear_force        = 0.; ///< N/m, in-plane shear per metre
    double closed_length      = 0.; ///< m, the line's contact length
    double peak_normal_stress = 0.; ///< Pa, the line's largest nodal traction
    /** The line's node pairs in order along the joint (the area's outline). */
    std::vector<JointNodeSample> profile;
  };

  /**
   * @brief Post-processed forces of one joint, per metre of face (2D: the
   * plane-strain model's metre; 3D: the totals over the face length
   * divided by it, make_swept_joint_reports()).
   */
  struct JointReport
  {
    std::string name;
    /** Integrated normal traction, the FEM "Q" of a vertical joint (N/m). */
    double normal_force = 0.;
    /** Integrated shear traction along the tangent (-n_y, n_x) (N/m). */
    double shear_force = 0.;
    /**
     * Length of the closed part (m); area = length x b in the 2D reading
     * over the support width. 3D: the contact area over the face length.
     */
    double closed_length = 0.;
    /**
     * Location uncertainty of the closed part's ends (m): over the ends
     * between nodes, the difference between the end rule used and a
     * second rule from other nodes (joint_report.cc,
     * alternative_closed_fraction()); 0 where no second rule applies.
     */
    double closed_length_uncertainty = 0.;
    /** Largest nodal normal traction (Pa) and where (m). */
    double           peak_normal_stress = 0.;
    dealii::Point<2> peak_position;
    /** 3D: z of the pointwise peak (m); 0 in 2D. */
    double peak_position_z = 0.;
    /** Largest normal traction averaged over
     * ContactSolverSettings::averaging_length (Pa). */
    double averaged_peak_normal_stress = 0.;
    double averaging_length            = 0.;
    /** normal_force / closed_length, 0 when open (Pa). */
    double      mean_normal_stress = 0.;
    StateCounts counts;
    /** 3D: the cross-section nearest the middle of the face. */
    std::vector<JointNodeSample> profile;
    /**
     * 3D scenes: length of face the joint runs along (m); the contact
     * area is closed_length x face_length, the total normal force
     * normal_force x face_length. 0 in 2D.
     */
    double face_length = 0.;
    /**
     * 3D scenes: the joint along the face, one entry per cross-section in
     * increasing z (a footprint's effect along the face); empty in 2D.
     */
    std::vector<JointSection> along_face;

    /** @brief True for a joint of a 3D scene (face_length > 0). */
    bool
    swept() const
    {
      return face_length > 0.;
    }
  };

  /**
   * @brief Global equilibrium check of one converged state, per metre of
   * face (N/m; 3D: the totals over the face length divided by it; 2D: the
   * z components are 0).
   */
  struct ForceBalance
  {
    dealii::Tensor<1, 3> applied_load;
    /** Dirichlet reactions plus the forces on rigid obstacles (N/m). */
    dealii::Tensor<1, 3> support_reaction;
    /** |applied + reaction| / (|applied| + sum of |nodal reactions|) (-). */
    double relative_imbalance = 0.;
  };

  /**
   * The floor's safety factors at one floor-level block corner
   * (Safety::CornerSafety), as an increment keeps them for the history
   * along the floor lift.
   */
  struct CornerFactors
  {
    std::string corner;         ///< "face block at vertical 6"
    double      point_factor;   ///< -, the point method's FS
    double      line_factor;    ///< -, the line method's FS
    double      area_factor;    ///< -, the area method's FS
    double      verdict_factor; ///< -, the factor the verdict goes by
    std::string verdict_method; ///< "line" or "area"
    bool        resolved;       ///< the mesh resolves the critical distance
  };

  /** @brief One converged increment. */
  struct IncrementResult
  {
    Loading::LoadStage stage = Loading::LoadStage::gravity;
    /** Fraction of the stage's load reached (-). */
    double stage_factor = 0.;
    /**
     * Of the start that converged; a discarded extrapolated start's
     * iterations count in SolveResult::n_failed_newton_iterations.
     */
    unsigned int n_newton_iterations = 0;
    /**
     * Rigid law: the increment was solved from a penalty start
     * (ExactFormulation::solve_from_penalty_start), whose iterations are
     * included in n_newton_iterations.
     */
    bool started_from_penalty = false;
    /** Failed attempts (cutbacks) before this increment converged. */
    unsigned int n_cutbacks = 0;
    /**
     * Rigid law: the complementarity parameter in force when this
     * increment converged, as a fraction of the configured one
     * (ExactFormulation::solve_increment lowers it to 0.1 or 0.01 to rescue a
     * load state whose active set cycles, and keeps it from then on);
     * 1 for the compliant law, which has no such parameter.
     */
    double complementarity_factor = 1.;
    double relative_residual      = 0.;
    /** Newton stopped on the round-off floor of the residual (see
     * NewtonIterate). */
    bool                     round_off_limited = false;
    StateCounts              counts;
    ForceBalance             balance;
    std::vector<JointReport> joints;
    /**
     * Rigid-body fit of every body; 3D: the x-y translation and the
     * rotation about z, averaged over the volume (u_z is not kept).
     */
    std::map<dealii::types::material_id, Fem::RigidMotion<2>> motions;
    /** 2D elastic FEM: every floor-level corner's safety factors at this
     * increment (Pipeline's increment observer); else empty. */
    std::vector<CornerFactors> corner_factors;
    double                     wall_time = 0.; ///< s
  };

  /** @brief All converged increments plus timing. */
  struct SolveResult
  {
    std::vector<IncrementResult> increments;
    /** Wall time per TimerOutput section ("Contact: assemble", ...) (s). */
    std::map<std::string, double> wall_times;
    unsigned int                  n_dofs          = 0;
    unsigned int                  n_contact_pairs = 0;
    /** Linear solves of all Newton iterations, failed increments included. */
    unsigned int n_linear_solves = 0;
    /** Numeric LU factorisations among them (direct solver only). */
    unsigned int n_factorizations = 0;
    /** GMRES iterations on stored or fresh LU factors (direct solver only). */
    unsigned int n_krylov_iterations = 0;
    /** ML AMG hierarchies built (iterative solver only). */
    unsigned int n_amg_setups = 0;
    /** GMRES iterations preconditioned by ML AMG (iterative solver only). */
    unsigned int n_amg_krylov_iterations = 0;
    /** Direct solutions accepted above the residual tolerance (ill-conditioned
     * matrix). */
    unsigned int n_solves_above_tolerance = 0;
    /** Newton iterations of failed attempts (cut back or retried), not in any
     * increment. */
    unsigned int n_failed_newton_iterations = 0;
  };

  /**
   * @brief The loading path could not be followed even after cutbacks.
   * Carries what was tried and the last converged increment; the solver's
   * solution() still holds that state.
   */
  class ContactSolveFailure : public std::runtime_error
  {
  public:
    ContactSolveFailure(const std::string             &message,
                        std::vector<std::string>       attempts,
                        std::optional<IncrementResult> last_converged,
                        const StateCounts             &last_iterate_counts)
      : std::runtime_error(message)
      , attempts(std::move(attempts))
      , last_converged(std::move(last_converged))
      , last_iterate_counts(last_iterate_counts)
    {}

    /** One line per failed attempt: stage, factor, reason. */
    std::vector<std::string>       attempts;
    std::optional<IncrementResult> last_converged;
    /** Open/stick/slip counts of the last Newton iterate tried. */
    StateCounts last_iterate_counts;
    /**
     * Everything up to the failure: every converged increment, the
     * counters (including the failed attempts' Newton iterations) and the
     * wall times; filled by ContactSolver::run().
     */
    SolveResult partial_result;
  };
} // namespace FloorBlock::Contact
