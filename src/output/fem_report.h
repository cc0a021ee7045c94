#pragma once

#include <compare/load_check.h>
#include <contact/results.h>
#include <geometry/assembly_mesher.h>
#include <safety/corner_safety.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Output
{
  /** Force balance of one converged increment. */
  struct IncrementBalance
  {
    /**
     * |applied load + support reactions| over the load; 0 for an increment
     * that carries no load (Compare::check_load), whose ratio would divide
     * round-off by round-off.
     */
    double relative_error = 0.;
    /** |applied load + support reactions| (N/m). */
    double absolute_error = 0.;
    bool   carries_load   = true;
  };

  /** The worst force balance over a solve's converged increments. */
  struct ForceBalanceSummary
  {
    /** Worst relative error over the increments that carry load. */
    double worst_relative_error = 0.;
    /** Worst absolute error over every increment (N/m). */
    double      worst_absolute_error = 0.;
    std::string status;      ///< "ok", "no load" or "no increment"
    std::string status_text; ///< what the worst error covers, in words
  };

  /** The work of a solve that failed after its cutbacks. */
  struct SolveFailureRecord
  {
    /** Cutbacks of the increment that failed for good. */
    unsigned int             cutbacks_before_failure = 0;
    std::vector<std::string> failed_attempts;
    /** Newton iterations of the failed attempts. */
    unsigned int n_failed_newton_iterations = 0;
  };

  /** Whether the joint sides overlap more than small strains allow. */
  struct OverlapCheck
  {
    double      largest_overlap = 0.; ///< m, over the last increment's joints
    double      limit           = 0.; ///< m, 5 % of the smaller block side
    bool        large           = false;
    std::string text; ///< the finding in words
  };

  /** What the rigid-block model is (Model/Blocks = rigid). */
  struct RigidModelNote
  {
    std::string  rigid_status; ///< RigidBlocks::to_string(status)
    unsigned int points_per_joint = 0;
    /** Geometry/Corner rounding radius (m), ignored by rigid blocks. */
    double corner_rounding_radius = 0.;
  };

  /**
   * The support load a 3D scene applies (Loading/Footprint length): the
   * footprint, if any, and the force the mesh carries, integrated over
   * the loaded faces (Fem::applied_surface_load()).
   */
  struct SweptSupportLoad
  {
    /** Loading/Support load (N), the force of one support. */
    double support_load = 0.;
    /** Total support force applied, its component along the vertical (N). */
    double applied_load = 0.;
    /** Area of the faces it acts on (m^2). */
    double loaded_area = 0.;
    /** Whether the load stands on a footprint (else along the whole face). */
    bool   on_footprint    = false;
    double footprint_start = 0.; ///< m along the face
    double footprint_end   = 0.; ///< m along the face
  };

  /**
   * The FEM report of one solve, besides the solver's own
   * Contact::SolveResult: model, status, totals over the increments, force
   * balance and the model's particulars. fem_json() writes it as fem.json.
   */
  struct FemReport
  {
    std::string  model;        ///< "elastic FEM" or "rigid blocks"
    std::string  model_choice; ///< why this model (Model/Blocks = auto)
    std::string  status;       ///< "converged" or "not converged"
    std::string  status_text;  ///< why, in words
    unsigned int n_blocks      = 0;
    double       support_width = 0.; ///< b (m): areas and forces "over b"
    /** Newton iterations of the converged increments. */
    unsigned int n_newton_iterations = 0;
    /** Cutbacks, including those of an increment that failed for good. */
    unsigned int n_cutbacks = 0;
    /** One per converged increment of the result. */
    std::vector<IncrementBalance>           increment_balances;
    ForceBalanceSummary                     force_balance;
    std::optional<SolveFailureRecord>       failure; ///< failed solves only
    std::optional<OverlapCheck>             joint_overlap; ///< elastic FEM only
    std::optional<Geometry::MeshStatistics> mesh;          ///< elastic FEM only
    std::optional<RigidModelNote>           rigid;        ///< rigid blocks only
    std::optional<SweptSupportLoad>         support_load; ///< 3D scenes only
    /** The floor's safety factor at every floor-level block corner
     * (Safety::corner_safety()); 2D elastic FEM only, else empty. */
    std::vector<Safety::CornerSafety> corner_safety;

    bool
    converged() const
    {
      return status == "converged";
    }
  };

  /**
   * @brief fem.json: the final joint table (chapter numbering, units in the
   * keys), per-increment statistics, DoFs, wall time per stage, the
   * force-balance error and the model's particulars. A run that stopped
   * early reports its last converged increment under the report's status.
   *
   * Every increment reports its absolute imbalance |applied load + support
   * reactions| in N/m; one that carries no load reports a relative error of
   * 0 with force_balance_status "no load".
   */
  nlohmann::json
  fem_json(const Contact::SolveResult &result, const FemReport &report);

  /** @brief One joint as the JSON object of fem.json's "joints" list. */
  nlohmann::json
  joint_json(const Contact::JointReport &joint,
             const unsigned int          n_blocks,
             const double                support_width);

  /** @brief joints.csv: one row per joint per converged increment. */
  std::string
  joints_csv(const Contact::SolveResult &result, const double support_width);

  /**
   * @brief joint_profiles.csv: one row per joint node pair at the last
   * increment of every stage, in arc order along each joint: position,
   * gap, nodal normal and shear traction, state. The contact-zone ends
   * and the corner stress fields of the joint tables, node by node (every
   * increment's state is in the VTU files).
   */
  std::string
  joint_profiles_csv(const Contact::SolveResult &result);

  /**
   * @brief The two bodies a joint separates, chapter numbering: [j, j+1] or
   * [n, "face"] for vertical joint j, [i, "base"] for the bedding under i.
   */
  nlohmann::json
  joint_bodies(const std::string &kind,
               const unsigned int number,
               const unsigned int n_blocks);

  /**
   * @brief Why an increment counts as unloaded, with its numbers: "the
   * applied load, the support reactions and every joint force are at most
   * ... N/m, ...".
   */
  std::string
  no_load_text(const Compare::LoadCheck &check);

  /**
   * @brief The force balance in words: "force balance error 1.2e-13
   * (3.4e-08 N/m)", "no load (force balance 2.1e-07 N/m, round-off)" or
   * "force balance: no increment".
   */
  std::string
  force_balance_text(const ForceBalanceSummary &balance);

  /** @brief A joint's state: "open", "stick", "slip" or "stick-slip". */
  std::string
  state_summary(const Contact::StateCounts &counts);

  /** @brief "stage 3 (uplift)" style name of a loading stage. */
  std::string
  stage_name(const Loading::LoadStage stage);
} // namespace FloorBlock::Output
