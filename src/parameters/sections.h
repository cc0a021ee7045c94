#pragma once

#include <contact/joint_law_kind.h>
#include <geometry/bedding_kinds.h>
#include <geometry/end_faces.h>
#include <parameters/uncertain_inputs.h>
#include <solver/solver_kinds.h>

#include <deal.II/base/parameter_handler.h>

#include <strength/hoek_brown.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

/**
 * One struct per subsection of a scene file. Each struct declares its entries
 * (with bounded patterns and "Units: ..." in the documentation) and parses
 * them, converting to SI once, here: angles to radians, tonnes-force to
 * newtons. Solver and analytic code receive these structs, never the
 * ParameterHandler.
 */
namespace FloorBlock::Parameters
{
  /** Subsection "Geometry": the block assembly. */
  struct GeometryParameters
  {
    unsigned int n_blocks;
    double       block_width;      ///< L (m), perpendicular to the face
    double       block_height;     ///< H (m)
    double       support_width;    ///< b (m), along the face
    double       face_block_width; ///< m
    double       base_thickness;   ///< m, the bedding layer below the blocks
    double       corner_rounding_radius; ///< m, 0 = sharp corners
    unsigned int dimension;              ///< 2 (plane strain) or 3 (extruded)
    double       face_length;            ///< m, along the face (z), 3D only
    Geometry::EndFaces end_faces;        ///< 3D only: plane strain or free

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** Subsection "Bedding": the failed bedding plane the blocks slide on. */
  struct BeddingParameters
  {
    Geometry::BeddingShape shape;
    Geometry::FloorUplift  floor_uplift;
    double
      inclination;     ///< rad, planar; positive when rising away from the face
    double curvature;  ///< k (m) in y = x^2/k, parabolic
    bool   rigid_base; ///< rigid half-plane instead of the elastic base
    double frame_dip;  ///< rad, dip of the frame's x axis below the horizontal

    /**
     * The bedding is the line y = 0 of the mesh (lifted reading, or a level
     * planar bed), so the block tops are level too.
     */
    bool
    flat_in_mesh() const;

    /**
     * @brief Rise of the bedding from the face to the free end x = nL (m),
     * as the closed forms place the blocks on it:
     * Analytic::parabolic_bedding_rise() or planar_bedding_rise().
     */
    double
    rise_at_free_end(unsigned int n_blocks, double block_width) const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** Subsection "Material": intact rock of blocks, face block and base. */
  struct MaterialParameters
  {
    double bulk_modulus;  ///< K (Pa)
    double shear_modulus; ///< G (Pa)
    double density;       ///< kg/m^3
    /// The entries left auto and what they were derived as, for
    /// parameters.prm: {"Young's modulus", "derived from K and G: ..."}.
    std::vector<std::pair<std::string, std::string>> derived_text;

    /** E = 9KG/(3K+G) (Pa). */
    double
    youngs_modulus() const;
    /** nu = (3K-2G)/(2(3K+G)). */
    double
    poissons_ratio() const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** Subsection "Strength": the rock's strength, SI. */
  struct StrengthParameters
  {
    double intact_ucs;         ///< sigma_ci (Pa)
    double m_i;                ///< Hoek-Brown m_i of the intact rock (-)
    double gsi;                ///< Geological Strength Index (-)
    double disturbance;        ///< D (-)
    double tensile_strength;   ///< sigma_t of the intact rock (Pa)
    double fracture_toughness; ///< K_Ic (Pa m^0.5)
    double critical_distance;  ///< L (m)

    /** @brief m_b, s and a of the rock mass (2002 edition). */
    Strength::HoekBrownConstants
    hoek_brown() const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** Where the compliant joints' kn and ks come from. */
  enum class JointStiffnessSource
  {
    given,        ///< Joints/Normal stiffness and Shear stiffness
    barton_bandis ///< the joint data (Strength::barton_bandis.h)
  };

  /** The Barton-Bandis entries of subsection "Joints", SI. */
  struct BartonBandisEntries
  {
    double                roughness_coefficient;   ///< JRC (-)
    double                wall_strength;           ///< JCS (Pa)
    std::optional<double> initial_aperture;        ///< a_j (m); empty: auto
    double                residual_friction_angle; ///< phi_r (rad)
    double                normal_stress;  ///< sigma_n (Pa), kn and ks at it
    std::optional<double> sheared_length; ///< L_x (m); empty: auto
  };

  /** Subsection "Joints": vertical fractures and the bedding plane. */
  struct JointParameters
  {
    double bedding_friction_angle;  ///< phi_h (rad)
    double vertical_friction_angle; ///< phi_v (rad)
    double cohesion;                ///< Pa
    double tensile_strength;        ///< Pa
    /// kn (Pa/m) of the compliant law: as given, or from the joint data
    /// once resolve_stiffness() ran.
    double                normal_stiffness;
    double                shear_stiffness; ///< ks (Pa/m), likewise
    Contact::JointLawKind law;
    JointStiffnessSource  stiffness_source;
    BartonBandisEntries   barton_bandis; ///< read for Barton-Bandis only
    /// The derived kn and ks with their inputs in words, for parameters.prm
    /// and the terminal; empty for Stiffness source = given.
    std::string stiffness_origin;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief For Stiffness source = Barton-Bandis: kn and ks from the joint
     * data at the entries' normal stress (joint_stiffness.cc), with the
     * auto aperture from Strength/Intact UCS and the auto sheared length
     * Geometry/Block height; sets stiffness_origin. Nothing for given.
     * @throws InputError naming the entry, its value and the range that
     * gives a positive, finite stiffness within the fits' validity.
     */
    void
    resolve_stiffness(const GeometryParameters &geometry,
                      const StrengthParameters &strength);
  };

  /** How the base moves in the floor-uplift stage. */
  enum class UpliftMode
  {
    vertical,        ///< translation straight up by the floor lift
    dip_toward_face, ///< translation along the bedding chord, toward the face
    dip_away_from_face, ///< translation along the bedding chord, away from it
    tilt,               ///< rotation about the free end; the face end rises
    parabola,           ///< bending u_y = lift (x / nL)^2, x from the face
    slope               ///< planar slope u_y = lift x / nL, x from the face
  };

  /** Subsection "Loading". */
  /** Which way the support load pushes on an inclined block top. */
  enum class SupportLoadDirection
  {
    vertical,  ///< straight down, as the closed forms' W_i + P_i
    top_normal ///< normal to the block top (a shield standing on it)
  };

  struct LoadingParameters
  {
    UpliftMode           uplift_mode;
    SupportLoadDirection support_load_direction;
    double               gravity;      ///< m/s^2
    double               support_load; ///< N, total load of one powered support
    /// Loaded blocks counted from the face (1 = next to the face block), as
    /// the user wrote them; Scene converts to the chapter's numbering.
    std::vector<unsigned int> loaded_blocks_from_face;
    /// m; for Floor lift = auto the bedding's rise, set by
    /// ScenarioParameters::parse_parameters() once the geometry is known.
    double floor_lift;
    /// Floor lift = auto: derived from the bedding.
    bool floor_lift_auto;
    /// Floor lift against bedding = may differ.
    bool floor_lift_may_differ;
    /// Where the floor lift comes from, in words, for parameters.prm and
    /// report.md ("auto: (nL)^2/k = ..."); empty for a number as written.
    std::string floor_lift_origin;
    /**
     * 3D scenes: the support's extent along the face (m), the shield
     * width b on which its whole Support load acts; 0 = no footprint, the
     * 2D per-metre load along the whole face length.
     */
    double footprint_length;
    /**
     * z of the footprint's start (m); empty = centred on the face
     * (Geometry/Face length - footprint_length) / 2.
     */
    std::optional<double> footprint_offset;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** Subsection "Mesh": element sizes for the Gmsh block assembly. */
  /** A face-joint figure that Mesh/Target relative error applies to. */
  enum class TargetFigure
  {
    normal_force,
    contact_length,
    sigma_max,
    sigma_max_averaged
  };

  struct MeshParameters
  {
    double corner_size; ///< m, target element size at joint corners
    double far_size;    ///< m, element size far from the corners
    double growth_rate; ///< size ratio between neighbouring elements, > 1
    bool   matching_joints;
    /**
     * deal.II refinements of the whole Gmsh mesh, each halving every cell
     * (new boundary vertices on the scene's curves); empty for "auto"
     * (Scene::global_refinements() decides).
     */
    std::optional<unsigned int> global_refinements;
    /**
     * Cells across the closed-form estimate of the face joint's contact
     * length (Scene::closed_form_contact_zones(), else a first solve:
     * Pipeline::contact_zone_sizing()); 0 = no contact-zone sizing.
     */
    unsigned int cells_per_contact_length;
    /** Cells across Strength/Critical distance L at the floor-level block
     * corners (Scene::critical_distance_sizes()); 0 = none. */
    unsigned int cells_per_critical_distance;
    /**
     * `run` refines adaptively until the estimated relative error of each
     * target figure of the face joint is at most this (1 = 100 %).
     */
    double target_relative_error;
    /** The face-joint figures the target applies to (TargetFigure). */
    std::vector<TargetFigure> target_figures;
    /** Largest number of adaptive levels after level 0 (each one solve). */
    unsigned int max_refinement_levels;
    /** Wall time (s) after which no further level is started. */
    double refinement_time_budget;
    /** Slice thickness (m) along the face of a 3D scene. */
    double slice_size;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
  /** Subsection "Solver": the contact FEM's numerics. */
  struct SolverParameters
  {
    /** The degree of a solve (1 when FE degree = auto). */
    unsigned int fe_degree;
    /** FE degree = auto: `run` races degrees 1 and 2 (degree_race.h). */
    bool                     choose_fe_degree;
    unsigned int             n_gravity_steps;
    bool                     gravity_with_support_load;
    unsigned int             n_support_steps;
    unsigned int             n_uplift_steps;
    Solver::LinearSolverKind linear_solver;
    unsigned int             max_direct_dofs;
    unsigned int max_reuse_iterations; ///< GMRES on stored LU factors
    Solver::DirectSolverKind direct_solver;
    double                   newton_tolerance; ///< relative to the load norm
    unsigned int             max_newton_iterations;
    unsigned int             max_cutbacks;
    double averaging_length; ///< m, for the averaged peak stress
    double complementarity_factor;
    /// Whether `run` solves further adaptive levels and reports the
    /// differences as the discretisation error estimate (accuracy_loop.h).
    bool estimate_error_by_refined_solve;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
  /** Subsection "Verify", nested "Hertz": inputs of `floorblock verify hertz`.
   */
  struct VerifyParameters
  {
    double       hertz_radius;               ///< R (m)
    double       hertz_line_load;            ///< P (N/m)
    double       hertz_youngs_modulus;       ///< E of the cylinder (Pa)
    double       hertz_poissons_ratio;       ///< nu of the cylinder
    unsigned int hertz_cells_per_half_width; ///< contact cell size a / N
    double       patch_pressure;             ///< patch test pressure (Pa)
    double       incline_margin; ///< |tan(alpha)/mu - 1| either side
    double       two_blocks_lateral_pressure; ///< Pa
    unsigned int two_blocks_cells_per_metre;  ///< structured mesh density
    double       punch_pressure;              ///< on the block top (Pa)
    unsigned int punch_corner_refinements;    ///< halvings at the corner

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** Which model of the blocks solves a scene (subsection "Model"). */
  enum class BlockModel
  {
    elastic,  ///< contact FEM: deformable blocks, face block and base
    rigid,    ///< rigid blocks, 3 DOF each, same joints (src/rigid/)
    automatic ///< chosen by the requested outputs (ModelParameters::choose)
  };

  /** What a run is asked for; decides Model/Blocks = auto. */
  enum class RequestedOutputs
  {
    forces,        ///< lateral forces Q_j and joint shear
    contact_stress ///< contact length/area and peak stress at the corners
  };

  /**
   * Subsection "Model": which level of the model hierarchy (closed form,
   * rigid blocks, elastic FEM) computes the numbers of `solve` and `run`.
   */
  struct ModelParameters
  {
    BlockModel       blocks; ///< as written (auto stays automatic)
    RequestedOutputs outputs;
    /// Trapezoid points per joint of the rigid-block model (>= 2).
    unsigned int rigid_points_per_joint;
    /// The model that runs (never automatic once choose() has run).
    BlockModel chosen = BlockModel::elastic;
    /// Why that model runs, in words (echoed into fem.json).
    std::string choice_reason;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Sets chosen and choice_reason: Blocks as written, or for auto
     * rigid when only forces are requested and the rigid model can
     * represent the scene, elastic otherwise.
     * @throws InputError for Blocks = rigid on a scene the rigid model
     * cannot represent (Joints/Law = rigid; a support load normal to an
     * inclined block top).
     */
    void
    choose(const BeddingParameters &bedding,
           const JointParameters   &joints,
           const LoadingParameters &loading);
  };

  /** Subsection "Corner": the `corner` command's analysis. */
  struct CornerParameters
  {
    /** Vertical joint whose floor-level corner is analysed (1..n). */
    unsigned int joint;
    /** Most zoom levels after the scene's mesh. */
    unsigned int max_zoom_levels;
    /** Relative change between zoom levels at which the peak counts as
     * converged. */
    double converged_change;
    /** Relative change between zoom levels at which K1 counts as converged. */
    double intensity_change;
    /** Corner rounding radii of the rounding study (m); empty: no study. */
    std::vector<double> rounding_radii;
    /** Wall time of the whole command (s). */
    double time_budget;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm, unsigned int n_blocks);
  };

  /**
   * Subsection "Uncertainty": the inputs `floorblock assess` treats as
   * random, and how it estimates the probability of failure P(FS < 1).
   * Other commands read it and leave it unused.
   */
  struct UncertaintyParameters
  {
    /** Uncertain scene parameters, each with its distribution. */
    std::vector<UncertainInput> inputs;
    /** Correlations of their Gaussian copula (others independent). */
    std::vector<InputCorrelation> correlations;
    /** Largest half-width of P_f's 95 % confidence interval (-). */
    double half_width = 0;
    /** FEM cases the surrogate is fitted on. */
    unsigned int training_cases = 0;
    /** FEM cases held out to check the surrogate. */
    unsigned int validation_cases = 0;
    /** FEM cases added where the surrogate's FS is near 1. */
    unsigned int refinement_cases = 0;
    /** Seed of every random design and sample. */
    unsigned int seed = 0;
    /** Wall time of the whole command (s). */
    double time_budget = 0;
    /** Path of the input the design limit curve runs over ("" = none). */
    std::string design_limit_input;
    /** Failure probabilities whose design limit is reported (-). */
    std::vector<double> design_limit_probabilities;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /**
     * Reads the subsection, and checks every input's path against @p prm:
     * a numeric parameter outside Uncertainty whose declared range holds
     * every value the distribution can take.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace FloorBlock::Parameters
