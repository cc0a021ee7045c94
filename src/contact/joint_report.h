#pragma once

#include <contact/contact_node.h>
#include <contact/joint_law.h>
#include <contact/results.h>

#include <string>
#include <vector>

namespace FloorBlock
{
  namespace Contact
  {
    /**
     * @brief Per-joint forces, closed length, peak and mean normal stress.
     *
     * Nodal tractions are the pair tractions; forces integrate them with the
     * lumped weights. The averaged peak is the largest weighted mean of
     * \f$t_n\f$ over a window of length @p averaging_length centred on a
     * node: the pointwise peak at a sharp corner grows without bound under
     * refinement, the averaged one converges.
     *
     * @param[in] nodes All contact pairs.
     * @param[in] responses Law evaluations of the converged state.
     * @param[in] names One name per joint; pairs refer to it by index.
     * @param[in] averaging_length Window length (m).
     */
    std::vector<JointReport>
    make_joint_reports(const std::vector<ContactNode<2>>   &nodes,
                       const std::vector<JointResponse<2>> &responses,
                       const std::vector<std::string>      &names,
                       const double                         averaging_length);

    /**
     * @brief Pointwise peak (and where), and the largest mean of t_n over a
     * window of length report.averaging_length, from report.profile.
     *
     * Each node's force w_i t_i is spread uniformly over its tributary
     * interval (midpoints to its neighbours), so a window integrates force,
     * whatever the node spacing; windows are centred on nodes and shifted to
     * stay inside the joint (the whole joint if it is shorter than the
     * window). Shared with the rigid-block model so both report the same
     * averaged peak.
     *
     * @param[in,out] report Profile sorted by arc_position, peaks zero.
     * @param[in] weights Length each profile node stands for (m).
     */
    void
    add_peak_stresses(JointReport &report, const std::vector<double> &weights);
  } // namespace Contact
} // namespace FloorBlock
