#pragma once

#include <analytic/asymptotic_fit.h>
#include <contact/results.h>
#include <corner/corner_site.h>

#include <vector>

namespace FloorBlock::Corner
{
  /** How the contact zone nearest a floor-level corner ends there. */
  enum class CornerContactKind
  {
    /**
     * The zone ends inside the corner fillet (or at its start), between
     * nodes: an incomplete contact with a smooth edge (both surfaces curve
     * away from each other).
     */
    edge_in_fillet,
    /** The zone reaches the joint's end: a complete contact at a sharp corner.
     */
    reaches_corner,
    /** The zone ends below the corner on the straight joint: the top is open.
     */
    open_at_corner
  };

  /** @brief "edge in fillet", "reaches corner", "open at corner". */
  const char *
  to_string(CornerContactKind kind);

  /**
   * @brief The face of the contact zone at a floor-level corner, read from
   * one joint profile: where the zone ends, its state there and the
   * traction against the distance from that end.
   *
   * Distances are arc lengths along the joint side's nodes, measured from
   * the end of the zone ("edge"): the located edge between nodes
   * (edge_in_fillet, open_at_corner) or the joint's last node
   * (reaches_corner).
   */
  struct CornerProfile
  {
    CornerContactKind kind = CornerContactKind::open_at_corner;
    /** Arc position of the site's corner on the profile (m). */
    double corner_arc = 0.;
    /** Arc position of the zone's end (m), "up" being towards the top. */
    double edge_arc = 0.;
    /** How far the zone's end lies above the corner (m, < 0 below it). */
    double edge_beyond_corner = 0.;
    /** State of the closed node nearest the end. */
    Contact::JointState edge_state = Contact::JointState::open;
    /** Shear over normal traction at that node (-). */
    double edge_traction_ratio = 0.;
    /** Node spacing at the end (m): the resolution of the zone's end. */
    double edge_spacing  = 0.;
    double peak_traction = 0.; ///< Pa, largest normal traction of the zone
    double peak_distance = 0.; ///< m, its distance from the end
    /** Normal traction (Pa) of every closed node of the zone against its
     *  distance from the end (m), nearest first; a node at the end itself
     *  (distance 0) is left out, the peak counts it. */
    std::vector<Analytic::RadialSample> samples;
    /** Reference position of each sample's node (m). */
    std::vector<dealii::Point<2>> sample_positions;
  };

  /**
   * @brief The contact zone at @p site's corner in @p joint's profile: the
   * closed node highest up the joint (towards the blocks' top) ends it.
   * The end between that node c and the open node above it lies where
   * t_n^2, extrapolated linearly from c and the closed node below it,
   * reaches zero (the exact law's square-root fall, the rule of
   * Postprocess::make_joint_reports' closed length), at most the open node.
   * @throws std::runtime_error if the profile has no closed node.
   */
  CornerProfile
  corner_profile(const Contact::JointReport &joint, const CornerSite &site);
} // namespace FloorBlock::Corner
