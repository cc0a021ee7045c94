#pragma once

#include <contact/results.h>
#include <geometry/local_size_field.h>
#include <parameters/scenario_parameters.h>

#include <optional>
#include <string>
#include <vector>

/**
 * @file How finely one solve's mesh is made from a scene: the global
 * halvings of the Gmsh mesh and the cells placed along the contact zones.
 * Refinement studies (src/studies/) drive these through Mesh/ parameters.
 */
namespace FloorBlock::Scene
{
  /** Most halvings "auto" asks for (64 times the cells). */
  constexpr unsigned int max_auto_global_refinements = 3;

  /**
   * @brief Joint compliance length E/kn (m): the length of rock whose
   * elastic compliance equals the joint's. 0 for the rigid law.
   */
  double
  joint_compliance_length(const Parameters::ScenarioParameters &scene);

  /**
   * @brief Whether the joints act as exact contact at the block corners:
   * the rigid law, or springs whose compliance length E/kn is below the
   * corner rounding radius. Then only the corner's own shape limits the
   * contact pressure, and the displacement is not smooth at the corners
   * and at the ends of the contact zones.
   */
  bool
  contact_is_exact(const Parameters::ScenarioParameters &scene);

  /**
   * @brief How many times the Gmsh mesh of @p scene is refined globally:
   * Mesh/Global refinements, or for "auto" the rule below.
   *
   * Why a rule depends on the joint law: where the joints are compliant
   * (E/kn at least the corner rounding radius r; the default scene:
   * 1.8 m against 1 cm) the springs spread the corner force over their
   * compliance length and the fillet does not matter. With exact contact
   * the fillet alone limits the concentration: the face joint's pressure
   * peaks 0.1-0.5 mm into the 1 cm fillet, and while the corner cells are
   * larger than r the fillet's compliance, hence the blocks' relative
   * rotation and the whole contact zone, moves with every refinement.
   * Measured on the default scene with the rigid law (nested ladder from
   * the 2 cm corner mesh): face contact length +23 %, +3.7 %, +0.12 % at
   * 30 deg, +28 %, -5.0 %, +0.43 % at 10 deg, +4.7 %, +5.4 %, +0.13 % at
   * 45 deg -- it settles once the corner cells are at most r. So "auto"
   * halves until Mesh/Corner size <= r in that case, and never for sharp
   * corners (no length to resolve); at most max_auto_global_refinements
   * times, since each halves every cell of the scene: a fillet much
   * smaller than the corner size asks for a smaller Mesh/Corner size,
   * which refines the corners only.
   */
  unsigned int
  global_refinements(const Parameters::ScenarioParameters &scene);

  /**
   * How far along a vertical joint, from each end, the contact-zone cells
   * reach, in estimated contact lengths c. More than 1 because Eq. 6.51 is
   * an estimate: on the default scene c = 459 mm against 348 mm computed
   * (+32 %); 1.5 also covers an estimate a third too short. A zone the
   * FEM computed gets the same half c beyond each of its ends.
   */
  constexpr double contact_zone_reach = 1.5;

  /**
   * @brief The closed-form contact length of the face joint (m), Eq. 6.51:
   * the shortest of the mechanisms whose corner contact has a length
   * (capped at the block height); empty when none has one or when the
   * closed forms describe another scene (ClosedForms::scene_differences).
   */
  std::optional<double>
  estimated_contact_length(const Parameters::ScenarioParameters &scene);

  /** Where the contact-zone sizes of a mesh come from. */
  enum class ContactZoneSource
  {
    not_asked,   ///< Mesh/Cells per contact length = 0
    closed_form, ///< Eq. 6.51's contact length (estimated_contact_length())
    first_solve, ///< the zones the FEM computed on the plain mesh
    none         ///< asked for, but neither gave a contact zone
  };

  /** @brief The contact-zone sizes of one mesh and where they came from. */
  struct ContactZoneSizing
  {
    ContactZoneSource source = ContactZoneSource::not_asked;
    /** The contact length the cells are sized from (m): Eq. 6.51's, or the
     * shortest the first solve computed; 0 without sizes. */
    double contact_length = 0.;
    /** Why there are no sizes (source none), in words. */
    std::string                      reason;
    std::vector<Geometry::LocalSize> sizes;
  };

  /** @brief "not_asked", "closed_form", "first_solve" or "none". */
  const char *
  source_key(ContactZoneSource source);

  /** @brief One line for the terminal and fem.json: where the sizes came
   * from, the contact length and the cell size. */
  std::string
  describe(const ContactZoneSizing &sizing, unsigned int cells_per_length);

  /**
   * @brief Size requests that put the ends of the contact zones in cells
   * sized from the scene: along both ends of every vertical joint, over
   * contact_zone_reach c from the end, points a cell apart asking for
   * cells of c / Mesh/Cells per contact length (not below Mesh/Corner
   * size); beyond them the sizes grow at Mesh/Growth rate. No sizes (source
   * none) when estimated_contact_length() has no answer: the pipeline then
   * sizes from a first solve (computed_contact_zones()).
   *
   * Why: the compliant joints' contact zone ends where the relative
   * rotation of the blocks closes the gap, and the corner grading alone
   * leaves that end in cells of 0.02 + 0.3 d m (12 cm at the default face
   * joint's 0.35 m). Measured on the default scene: face contact length
   * 341.2 mm on the graded mesh, 345.0 mm with 6 cm cells over the face
   * joint's upper 0.5 m, against 347.8 mm converged, at 3 % more DoFs.
   * The face joint's estimate serves every vertical joint: it carries the
   * largest force, so its zone is the shortest, and longer zones are then
   * over-resolved, never under-resolved.
   */
  ContactZoneSizing
  closed_form_contact_zones(const Parameters::ScenarioParameters &scene);

  /**
   * @brief Size requests from the contact zones a solve computed, for the
   * scenes Eq. 6.51 has no answer for (the joint closes at its foot, no
   * mechanism admissible, another scene than the closed forms').
   *
   * On every vertical joint of @p joints (is_vertical_joint())
   * with a closed part, from its first to its last closed node
   * (JointReport::profile) and half its contact length c beyond either
   * end, within the joint: points a cell apart asking for cells of
   * c / Mesh/Cells per contact length (not below Mesh/Corner size), each
   * joint from its own c, since here the zones may sit at either end of
   * the joint and need not share the face joint's length. Source none when
   * no vertical joint is closed.
   */
  ContactZoneSizing
  computed_contact_zones(const Parameters::ScenarioParameters    &scene,
                         const std::vector<Contact::JointReport> &joints);

  /** How far along each corner's bisector the critical-distance cells
   * reach, in critical distances L: the line method reads the stress over
   * L, and a half L beyond keeps the grading out of it. */
  constexpr double critical_distance_reach = 1.5;

  /**
   * @brief Size requests for the floor safety factor: cells of L / N
   * (Strength/Critical distance L, N = Mesh/Cells per critical distance,
   * not below Geometry::min_relative_local_size of the smaller block
   * side) along the inward bisectors of both top corners of every
   * vertical joint, from the corner out to critical_distance_reach L: the
   * paths src/safety/ reads the stresses along. Gmsh's size field and
   * Pipeline::refine_corner_paths() both take them. Empty when N = 0 and
   * for 3D scenes (the safety factors come from 2D solves).
   */
  std::vector<Geometry::LocalSize>
  critical_distance_sizes(const Parameters::ScenarioParameters &scene);
} // namespace FloorBlock::Scene
