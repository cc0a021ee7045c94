#pragma once

#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace FloorBlock::Studies
{
  /** The compliant law's normal stiffnesses of the sweep (Pa/m). */
  inline const std::vector<double> kn_safety_normal_stiffnesses =
    {1e9, 3e9, 1e10, 3e10, 1e11, 1e12};

  /**
   * Cells per critical distance of the sweep where the scene asks for none
   * (Mesh/Cells per critical distance = 0): unresolved corner paths give
   * no factor. Cells of L/16 asked for leave a margin below the L/4 a
   * path needs (Safety::min_cells_per_critical_distance): the cells along
   * the paths come out larger (2.1-2.6 mm for L/16 = 0.6 mm on the default
   * scene, where the smallest corner cell is 1e-3 of the block width).
   */
  constexpr unsigned int kn_safety_cells_per_critical_distance = 16;

  /** One solve of the sweep and the floor's safety factor it gives. */
  struct KnSafetyCase
  {
    Contact::JointLawKind law = Contact::JointLawKind::compliant;
    double normal_stiffness   = 0.; ///< kn (Pa/m); 0 for the rigid law
    double shear_stiffness    = 0.; ///< ks (Pa/m); 0 for the rigid law
    /// "holds", "fails" (governing corner resolved), "unresolved" or
    /// "not converged"; the factors exist for the first two only.
    std::string           status;
    std::optional<double> point_factor; ///< FS, point method (L/2)
    std::optional<double> line_factor;  ///< FS, line method (mean over L)
    std::optional<double> area_factor;  ///< FS, area method (mean within L)
    /// The method the verdict goes by: "line" (compliant), "area" (rigid).
    std::string           verdict_method;
    std::string governing_corner; ///< "block 6 at vertical 6"; empty if none
    /// The face corner, the face block's at the face joint: its status
    /// ("holds", "fails", "unresolved", "not converged") and factors,
    /// which exist where it is resolved even if another corner governs.
    std::string           face_status;
    std::optional<double> face_point_factor;
    std::optional<double> face_line_factor;
    std::optional<double> face_area_factor;
    unsigned int          n_cells = 0; ///< of the mesh solved on
    std::string           folder;      ///< where the solve's files are
  };

  /** What the sweep solved, and on which mesh setting. */
  struct KnSafetySweep
  {
    std::vector<KnSafetyCase> cases;     ///< by kn, the rigid law last
    double       critical_distance = 0.; ///< Strength/Critical distance (m)
    unsigned int cells_per_critical_distance = 0;  ///< as solved
    double       stiffness_ratio             = 0.; ///< ks/kn of the scene, kept
  };

  /**
   * @brief Throws InputError, naming the entry, if `sweep --figure
   * kn_safety` cannot solve @p scene: the rigid-block model (no stresses
   * in the floor) or several MPI processes (the cases run one after the
   * other on one). Call before writing anything.
   */
  void
  check_kn_safety_scene(const Parameters::ScenarioParameters &scene);

  /**
   * @brief The floor's safety factor at the face against the joints'
   * normal stiffness: @p scene solved by Pipeline::solve_scene() with the
   * compliant law at every kn of kn_safety_normal_stiffnesses (ks = kn
   * times the scene's ks/kn, so the joints' shear-to-normal ratio stays),
   * then once with Joints/Law = rigid, the exact contact that kn -> infinity
   * approaches. Each solve's files go to @p folder's kn_safety/<case>/
   * (no VTU). The factors are fem.json's governing corner
   * (Safety::governing_corner()) and the face corner's. The rigid law's
   * mesh follows the scene's rules for it (Mesh/Global refinements = auto
   * refines it where the compliant law's E/kn does not).
   * @param[in] progress Called with one line of text per case as it
   *   finishes, and first with a note if the mesh setting was changed.
   */
  KnSafetySweep
  kn_safety_sweep(const Parameters::ScenarioParameters   &scene,
                  const Output::ResultFolder             &folder,
                  const std::function<void(std::string)> &progress);
} // namespace FloorBlock::Studies
