#pragma once

#include <contact/joint_law.h>
#include <contact/joint_law_kind.h>
#include <contact/newton_driver.h>
#include <fem/elastic_model.h>
#include <loading/load_steps.h>
#include <solver/linear_solver.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <string>
#include <vector>

namespace FloorBlock::Contact
{
  /**
   * @brief One joint: two boundary ids with matching nodes, or one boundary
   * id against a fixed rigid plane.
   */
  template <int dim>
  struct JointDefinition
  {
    /** Name used in reports, e.g. "vertical 6" (chapter numbering). */
    std::string                name;
    dealii::types::boundary_id side_a = 0;
    dealii::types::boundary_id side_b = 0;
    JointLawKind               law    = JointLawKind::compliant;
    /** kn and ks are used by the compliant law only. */
    JointConstants parameters;
    /** If true, side_b is ignored and side_a meets the plane below. */
    bool               against_rigid_plane = false;
    dealii::Point<dim> plane_point;
    /** Unit normal from the body into the obstacle. */
    dealii::Tensor<1, dim> plane_normal;
    /**
     * Curvature of a rigid parabolic obstacle (1/m), 0 for the plane: its
     * surface recedes from the plane by curvature s^2 / 2 at distance s
     * from plane_point along the plane, e.g. a rigid cylinder of radius
     * R = 1/curvature touching the plane at plane_point. The contact
     * normal stays the plane's (Hertz's small-slope approximation). Fixed
     * in space: refused together with plane_moves_with_uplift.
     */
    double obstacle_curvature = 0.;
    /**
     * The plane is displaced by the uplift (UpliftSettings at its point,
     * scaled by the stage-3 factor), e.g. a rigid bedding moved parallel
     * to itself; false: fixed.
     */
    bool plane_moves_with_uplift = false;
  };

  /** @brief A boundary with prescribed displacement components. */
  template <int dim>
  struct SupportDefinition
  {
    dealii::types::boundary_id boundary_id = 0;
    std::array<bool, dim>      constrained_components{};
    /** Fixed (false) or moved by the uplift (true). */
    bool moves_with_uplift = false;
  };

  /** How the moved supports (the base) are displaced in stage 3. */
  enum class UpliftMotion
  {
    vertical_translation, ///< u = (0, magnitude)
    dip_translation, ///< u = magnitude (cos dip, sin dip); sign picks the way
    tilt,            ///< rotation by magnitude (rad) about the pivot
    parabola, ///< u_y = (x - pivot_x)^2 / magnitude for x > pivot_x, else 0 (y
              ///< = x^2/k)
    slope     ///< u_y = magnitude (x - pivot_x) for x > pivot_x, else 0 (planar
              ///< slope)
  };

  /** @brief The prescribed floor uplift at the end of stage 3. */
  struct UpliftSettings
  {
    UpliftMotion mode = UpliftMotion::vertical_translation;
    /** m for translations, rad for tilt, the length k (m) for parabola, the
     * gradient (-) for slope. */
    double magnitude = 0.;
    /** Direction of dip_translation, from +x towards +y (rad). */
    double dip_angle = 0.;
    /** Pivot of tilt, vertex of the parabola, foot of the slope (m). */
    double pivot_x = 0.;
    double pivot_y = 0.;
  };

  /**
   * @brief Everything the physics needs: bulk model (full gravity and
   * pressures), joints, supports and the loading path.
   */
  template <int dim>
  struct ContactProblem
  {
    Fem::ElasticModel<dim>              model;
    std::vector<JointDefinition<dim>>   joints;
    std::vector<SupportDefinition<dim>> supports;
    UpliftSettings                      uplift;
    Loading::LoadSteps                  steps;
  };

  /** @brief Numerical settings of the contact solver. */
  struct ContactSolverSettings
  {
    /** FE_Q degree, 1 or 2. */
    unsigned int                 fe_degree = 1;
    NewtonSettings               newton;
    Solver::LinearSolverSettings linear;
    /** Halvings of a failed increment before giving up. */
    unsigned int max_cutbacks = 6;
    /**
     * Rigid law: complementarity parameter c_n = c_t of a pair = this
     * factor times the largest Young's modulus over the pair's length
     * (its weight, at least the smallest cell diameter) (-). It changes
     * the Newton iterates, never the converged answer (ExactContact).
     * Below the surface stiffness the multipliers, not the gaps, decide
     * the iterates' contact states, and Newton needs far fewer steps
     * (src/contact/README.md, "Complementarity parameter").
     */
    double complementarity_factor = 0.1;
    /**
     * Start each increment after the first of a stage from the linear
     * extrapolation of the last converged increment of the same stage,
     * instead of from the last converged state. Changes only where
     * Newton starts, not the equations of the increment.
     */
    bool extrapolate_increments = true;
    /**
     * Length over which the averaged peak normal stress is taken (m); read
     * by the post-processing (Postprocess::solve_with_reports).
     */
    double averaging_length = 0.1;
    /**
     * If not empty, a .pvd/.vtu series is written here per increment by
     * the post-processing (Postprocess::solve_with_reports).
     */
    std::string output_directory;
    /** Print one line per increment to stdout. */
    bool verbose = false;
  };
} // namespace FloorBlock::Contact
