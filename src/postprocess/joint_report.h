#pragma once

#include <contact/contact_node.h>
#include <contact/joint_law.h>
#include <contact/results.h>

#include <string>
#include <vector>

namespace FloorBlock::Postprocess
{
  /**
   * @brief Contact indicator of one pair: positive when closed, negative
   * when open, zero at the end of a closed zone.
   *
   * \f$\phi = \lambda_n/k - g\f$ in units of length, with \f$k\f$ the
   * pair's JointResponse::closure_stiffness. Closed pair: \f$\phi =
   * t_n/k\f$; open pair: \f$\phi = -g\f$ (\f$\lambda_n = 0\f$).
   *
   * Compliant law (\f$t_n = -k_n g\f$, \f$k = k_n\f$): \f$\phi = -g\f$
   * on both sides, so the zero of its linear interpolation is the zero of
   * the gap, which is linear along a degree-1 element edge. Exact law
   * (closed \f$g = 0\f$, open \f$\lambda_n = 0\f$): \f$\phi\f$ is the
   * pressure over the surface stiffness E / h on the closed side and
   * minus the gap on the open side, both zero at the end, so pressure and
   * gap weigh alike; the scale is the mesh's, never the complementarity
   * parameter, which must not change a result. Either way \f$\phi\f$ is
   * a continuous function of the solution, so the interpolated end moves
   * continuously when a pair changes state. A compliant joint with
   * \f$k_n \gg E/h\f$ puts the end next to its last closed node.
   *
   * @param[in] response Law evaluation of the pair.
   * @return \f$\phi\f$ (m); NaN for a closed pair without a positive
   *   closure stiffness (nothing to scale with).
   */
  double
  contact_indicator(const Contact::JointResponse<2> &response);

  /**
   * @brief How far beyond its last closed node an exact-law contact zone
   * ends (m): the normal traction of an incomplete-contact edge falls
   * like the square root of the distance to the end, so $t_n^2$ is
   * linear there and is extrapolated to zero from the last closed node
   * (@p end_traction, clamped at 0) and the closed node @p spacing (m)
   * further inside (@p inner_traction):
   * $d = t_e^2 s / (t_i^2 - t_e^2)$.
   * @pre @p inner_traction > max(0, @p end_traction): the traction falls
   *   toward the end (callers use another rule otherwise).
   */
  double
  square_root_edge_extent(const double end_traction,
                          const double inner_traction,
                          const double spacing);

  /**
   * @brief Per-joint forces, closed length, peak and mean normal stress.
   *
   * Nodal tractions are the pair tractions; the normal and shear forces
   * are the components of their resultant (lumped weights) along the
   * joint's reference normal and tangent: the normal shared by most of
   * the joint's weight (its straight part), or the weighted mean normal
   * on a curved joint. The averaged peak is the largest weighted mean of
   * \f$t_n\f$ over a window of length @p averaging_length centred on a
   * node: the pointwise peak at a sharp corner grows without bound under
   * refinement, the averaged one converges.
   *
   * Closed length: the measure of the part of the joint where the linear
   * interpolation of contact_indicator() between neighbouring nodes (in
   * arc order) is >= 0, capped by the joint's end nodes. Each node's
   * weight is split between its two neighbouring segments in proportion
   * to their lengths (an end node gives all of it to its one segment), so
   * a segment stands for the length of joint its two shares cover (its
   * own length for straight joints of degree 1 or 2). A segment between
   * two closed nodes counts whole, between two open ones not at all;
   * between a closed node c and an open node o it counts the fraction
   * \f$\phi_c / (\phi_c - \phi_o)\f$ from c (compliant law), or, for
   * the exact law's tractions (JointResponse::exact_traction), which fall
   * like the square root of the distance to the end, the distance at
   * which \f$t_n^2\f$, extrapolated linearly from c and the next closed
   * node c' beyond it, reaches zero: \f$t_c^2 |s_c - s_{c'}| / (t_{c'}^2 -
   * t_c^2)\f$, at most the whole segment (needs \f$t_{c'} > t_c\f$;
   * otherwise the indicator rule). Measured in src/contact/README.md
   * ("Closed length"). All nodes closed: the sum
   * of the weights; all open: 0. Where the indicator does not change sign
   * across such a segment (a closed pair held in tension by an intact
   * tensile strength, \f$\phi_c < 0\f$) the segment keeps c's share, the
   * node-count measure.
   *
   * @param[in] nodes All contact pairs.
   * @param[in] responses Law evaluations of the converged state.
   * @param[in] names One name per joint; pairs refer to it by index.
   * @param[in] averaging_length Window length (m).
   */
  std::vector<Contact::JointReport>
  make_joint_reports(const std::vector<Contact::ContactNode<2>>   &nodes,
                     const std::vector<Contact::JointResponse<2>> &responses,
                     const std::vector<std::string>               &names,
                     const double averaging_length);

  /**
   * @brief Pointwise peak (and where), and the largest mean of t_n over a
   * window of length report.averaging_length, from report.profile.
   *
   * Each node's force w_i t_i is spread uniformly over an interval of
   * its own length w_i, the intervals laid end to end in arc order (on a
   * straight degree-1 joint: its tributary, midpoints to its
   * neighbours), so a
   * window integrates force whatever the node spacing and its mean never
   * exceeds the pointwise peak; windows are centred on nodes' intervals
   * and shifted to stay inside the joint (the whole joint if it is
   * shorter than the window). Shared with the rigid-block model so both report
   * the same averaged peak.
   *
   * @param[in,out] report Profile sorted by arc_position, peaks zero.
   * @param[in] weights Length each profile node stands for (m).
   */
  void
  add_peak_stresses(Contact::JointReport      &report,
                    const std::vector<double> &weights);

  /**
   * @brief Largest overlap of the two sides of any joint (m, >= 0): minus
   * the most negative gap of all profile nodes. The compliant law lets
   * the sides overlap by t_n / k_n; the contact is small-strain and
   * node-to-node, so an overlap that is not small against the blocks
   * means that k_n is too soft for the loads.
   */
  double
  largest_overlap(const std::vector<Contact::JointReport> &joints);
} // namespace FloorBlock::Postprocess
