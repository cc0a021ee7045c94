#include <postprocess/joint_report.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace FloorBlock::Postprocess
{
  using namespace Contact;

  namespace
  {
    /** Rotates the normal by +90 degrees: the 2D joint tangent. */
    dealii::Tensor<1, 2>
    tangent_of(const dealii::Tensor<1, 2> &normal)
    {
      dealii::Tensor<1, 2> tangent;
      tangent[0] = -normal[1];
      tangent[1] = normal[0];
      return tangent;
    }

    /** Normals closer than this (-) count as one direction. */
    constexpr double same_normal_tolerance = 1e-9;

    /**
     * Reference normal of a joint: the node normal carrying most of the
     * weight (the straight part; fillet nodes at rounded corners turn
     * away from it), or, on a curved joint where no normal carries half
     * the weight, the weighted mean normal (the chord's normal).
     */
    dealii::Tensor<1, 2>
    reference_normal(const std::vector<ContactNode<2>> &nodes,
                     const std::vector<unsigned int>   &members)
    {
      std::vector<std::pair<dealii::Tensor<1, 2>, double>> groups;
      dealii::Tensor<1, 2>                                 weighted_sum;
      double                                               total_weight = 0.;
      for (const unsigned int p : members)
        {
          const ContactNode<2> &node = nodes[p];
          weighted_sum += node.weight * node.normal;
          total_weight += node.weight;
          auto group =
            std::find_if(groups.begin(),
                         groups.end(),
                         [&](const auto &candidate) {
                           return (candidate.first - node.normal).norm() <
                                  same_normal_tolerance;
                         });
          if (group == groups.end())
            groups.emplace_back(node.normal, node.weight);
          else
            group->second += node.weight;
        }
      const auto heaviest = std::max_element(groups.begin(),
                                             groups.end(),
                                             [](const auto &a, const auto &b) {
                                               return a.second < b.second;
                                             });
      if (heaviest->second >= total_weight / 2. || !(weighted_sum.norm() > 0.))
        return heaviest->first;
      return weighted_sum / weighted_sum.norm();
    }

    /**
     * Parts of each node's weight on the segment to its previous (first)
     * and next (second) neighbour in arc order, in proportion to the
     * segment lengths; an end node gives all of its weight to its one
     * segment.
     */
    std::vector<std::pair<double, double>>
    weight_shares(const std::vector<JointNodeSample> &profile,
                  const std::vector<double>          &weights)
    {
      const unsigned int                     n_nodes = profile.size();
      std::vector<std::pair<double, double>> shares(n_nodes, {0., 0.});
      for (unsigned int k = 0; k < n_nodes; ++k)
        {
          const double to_previous =
            k == 0 ? 0. : profile[k].arc_position - profile[k - 1].arc_position;
          const double to_next =
            k + 1 == n_nodes ?
              0. :
              profile[k + 1].arc_position - profile[k].arc_position;
          const double span = to_previous + to_next;
          if (span > 0.)
            shares[k] = {weights[k] * to_previous / span,
                         weights[k] * to_next / span};
        }
      return shares;
    }

    /**
     * Fraction of the segment from the closed node @p closed to its open
     * neighbour @p open that is closed (see make_joint_reports()).
     * Exact-law tractions fall like the square root of the distance to
     * the end of the zone, so t_n^2 is linear there: extrapolated from
     * @p closed and the next closed node beyond it to zero. Elsewhere
     * (compliant springs: gap and traction linear along a degree-1 edge;
     * a zone of one node) the zero of the linear interpolation of the
     * contact indicator. NaN when neither applies.
     */
    double
    closed_fraction(const std::vector<JointNodeSample> &profile,
                    const std::vector<double>          &indicators,
                    const unsigned int                  closed,
                    const unsigned int                  open)
    {
      const bool inward_up = closed > open;
      const bool has_next =
        inward_up ? closed + 1 < profile.size() : closed > 0;
      const unsigned int     next     = inward_up ? closed + 1 : closed - 1;
      const JointNodeSample &end_node = profile[closed];
      if (end_node.exact_traction && has_next &&
          profile[next].state != JointState::open &&
          profile[next].exact_traction)
        {
          const double p_end  = std::max(0., end_node.normal_traction);
          const double p_next = profile[next].normal_traction;
          const double segment =
            std::abs(profile[open].arc_position - end_node.arc_position);
          if (p_next > p_end && segment > 0.)
            return std::min(
              1.,
              square_root_edge_extent(p_end,
                                      p_next,
                                      std::abs(profile[next].arc_position -
                                               end_node.arc_position)) /
                segment);
        }
      const double inside  = indicators[closed];
      const double outside = indicators[open];
      // Also false for a NaN indicator.
      if (!(inside >= 0. && outside < 0.))
        return std::numeric_limits<double>::quiet_NaN();
      return inside / (inside - outside);
    }

    /**
     * The closed fraction of the same segment by a second, independent end
     * rule, for the end's location uncertainty (JointReport::
     * closed_length_uncertainty): where closed_fraction() extrapolates the
     * exact law's t_n^2 from the end node and the next, this extrapolates
     * it from the next two closed nodes; where it interpolates the
     * indicator linearly, this interpolates the quadratic through the two
     * nodes and the next open node beyond (the gap is smooth across the
     * end of a compliant zone: the springs' traction starts from zero).
     * NaN when the nodes for it are missing.
     */
    double
    alternative_closed_fraction(const std::vector<JointNodeSample> &profile,
                                const std::vector<double>          &indicators,
                                const unsigned int                  closed,
                                const unsigned int                  open)
    {
      const double nan     = std::numeric_limits<double>::quiet_NaN();
      const int    inward  = closed > open ? 1 : -1;
      const int    n_nodes = static_cast<int>(profile.size());
      const auto   node_at = [&](const int step) -> int {
        const int index = static_cast<int>(closed) + step * inward;
        return index >= 0 && index < n_nodes ? index : -1;
      };
      const double s_closed = profile[closed].arc_position;
      const double segment  = std::abs(profile[open].arc_position - s_closed);
      if (!(segment > 0.))
        return nan;
      const JointNodeSample &end_node = profile[closed];
      if (end_node.exact_traction)
        {
          const int next = node_at(1), beyond = node_at(2);
          if (next < 0 || beyond < 0 ||
              profile[next].state == JointState::open ||
              profile[beyond].state == JointState::open)
            return nan;
          const double p1 = profile[next].normal_traction;
          const double p2 = profile[beyond].normal_traction;
          if (!(p2 > p1 && p1 > 0.))
            return nan;
          const double spacing =
            std::abs(profile[beyond].arc_position - profile[next].arc_position);
          // Zero of the line through (s_next, p1^2), (s_beyond, p2^2),
          // measured outward from the next node, then from the end node.
          const double from_next = p1 * p1 * spacing / (p2 * p2 - p1 * p1);
          const double from_end =
            from_next - std::abs(profile[next].arc_position - s_closed);
          return std::clamp(from_end / segment, 0., 1.);
        }
      const int far = static_cast<int>(open) - inward;
      if (far < 0 || far >= n_nodes || profile[far].state != JointState::open)
        return nan;
      const double s[3] = {profile[far].arc_position,
                           profile[open].arc_position,
                           s_closed};
      const double g[3] = {indicators[far],
                           indicators[open],
                           indicators[closed]};
      if (!(g[2] >= 0. && g[1] < 0.) || std::isnan(g[0]))
        return nan;
      // Lagrange quadratic through the three; its zero between the open
      // and the closed node by bisection (the signs differ there).
      const auto quadratic = [&](const double x) {
        double value = 0.;
        for (int i = 0; i < 3; ++i)
          {
            double basis = 1.;
            for (int j = 0; j < 3; ++j)
              if (j != i)
                basis *= (x - s[j]) / (s[i] - s[j]);
            value += g[i] * basis;
          }
        return value;
      };
      double open_side = s[1], closed_side = s[2];
      for (int iteration = 0; iteration < 60; ++iteration)
        {
          const double middle = 0.5 * (open_side + closed_side);
          (quadratic(middle) < 0. ? open_side : closed_side) = middle;
        }
      return std::abs(0.5 * (open_side + closed_side) - s_closed) / segment;
    }

    /**
     * Closed length with interpolated contact ends (see
     * make_joint_reports()): the closed nodes' weights, and on every
     * segment between a closed and an open node the interpolated closed
     * part of the segment instead of the closed node's share. Written as
     * a correction of the node measure so that all-closed and all-open
     * joints give exactly the sums they gave before.
     */
    std::pair<double, double>
    interpolated_closed_length(const std::vector<JointNodeSample> &profile,
                               const std::vector<double>          &weights,
                               const std::vector<double>          &indicators)
    {
      double length      = 0.;
      double uncertainty = 0.;
      for (unsigned int k = 0; k < profile.size(); ++k)
        if (profile[k].state != JointState::open)
          length += weights[k];
      const auto shares = weight_shares(profile, weights);
      for (unsigned int k = 0; k + 1 < profile.size(); ++k)
        {
          const bool first_closed  = profile[k].state != JointState::open;
          const bool second_closed = profile[k + 1].state != JointState::open;
          if (first_closed == second_closed)
            continue;
          const double closed_share =
            first_closed ? shares[k].second : shares[k + 1].first;
          const double segment  = shares[k].second + shares[k + 1].first;
          const double fraction = closed_fraction(profile,
                                                  indicators,
                                                  first_closed ? k : k + 1,
                                                  first_closed ? k + 1 : k);
          // NaN: keep the node measure.
          if (std::isnan(fraction))
            continue;
          length += fraction * segment - closed_share;
          const double alternative =
            alternative_closed_fraction(profile,
                                        indicators,
                                        first_closed ? k : k + 1,
                                        first_closed ? k + 1 : k);
          if (!std::isnan(alternative))
            uncertainty += std::abs(alternative - fraction) * segment;
        }
      return {length, uncertainty};
    }
  } // namespace

  double
  square_root_edge_extent(const double end_traction,
                          const double inner_traction,
                          const double spacing)
  {
    const double end = std::max(0., end_traction);
    return end * end * spacing / (inner_traction * inner_traction - end * end);
  }

  double
  contact_indicator(const JointResponse<2> &response)
  {
    if (response.state == JointState::open)
      return -response.gap;
    const double normal_stiffness = response.closure_stiffness;
    if (!(normal_stiffness > 0.))
      return std::numeric_limits<double>::quiet_NaN();
    return response.normal_traction / normal_stiffness;
  }

  void
  add_peak_stresses(JointReport &report, const std::vector<double> &weights)
  {
    const auto        &profile = report.profile;
    const unsigned int n_nodes = profile.size();
    // Each node's force w_k t_k is spread over an interval of length w_k,
    // the intervals laid end to end in arc order: on a straight degree-1
    // joint these are the tributaries; where weights and node distances
    // differ (fillets, degree 2) a window mean still integrates the force
    // exactly and never exceeds the largest nodal traction.
    std::vector<double> lower(n_nodes), upper(n_nodes);
    double              reached = 0.;
    for (unsigned int k = 0; k < n_nodes; ++k)
      {
        lower[k] = reached;
        reached += weights[k];
        upper[k] = reached;
      }
    const double joint_start = 0.;
    const double joint_end   = reached;
    const double window_length =
      std::min(report.averaging_length, joint_end - joint_start);
    for (unsigned int centre = 0; centre < n_nodes; ++centre)
      {
        if (profile[centre].normal_traction > report.peak_normal_stress)
          {
            report.peak_normal_stress = profile[centre].normal_traction;
            report.peak_position      = profile[centre].position;
          }
        if (!(window_length > 0.))
          continue;
        const double start =
          std::clamp((lower[centre] + upper[centre] - window_length) / 2.,
                     joint_start,
                     joint_end - window_length);
        const double end   = start + window_length;
        double       force = 0.;
        for (unsigned int k = 0; k < n_nodes; ++k)
          {
            const double length = upper[k] - lower[k];
            if (!(length > 0.))
              continue;
            const double overlap =
              std::max(0., std::min(end, upper[k]) - std::max(start, lower[k]));
            force += weights[k] * profile[k].normal_traction * overlap / length;
          }
        report.averaged_peak_normal_stress =
          std::max(report.averaged_peak_normal_stress, force / window_length);
      }
  }

  std::vector<JointReport>
  make_joint_reports(const std::vector<ContactNode<2>>   &nodes,
                     const std::vector<JointResponse<2>> &responses,
                     const std::vector<std::string>      &names,
                     const double                         averaging_length)
  {
    std::vector<JointReport>               reports(names.size());
    std::vector<std::vector<unsigned int>> members(names.size());
    for (unsigned int p = 0; p < nodes.size(); ++p)
      members[nodes[p].joint].push_back(p);

    for (unsigned int j = 0; j < names.size(); ++j)
      {
        JointReport &report     = reports[j];
        report.name             = names[j];
        report.averaging_length = averaging_length;
        if (members[j].empty())
          continue;
        const ContactNode<2>      &first  = nodes[members[j].front()];
        const dealii::Tensor<1, 2> normal = reference_normal(nodes, members[j]);
        const dealii::Tensor<1, 2> tangent = tangent_of(normal);
        std::sort(members[j].begin(),
                  members[j].end(),
                  [&](const unsigned int a, const unsigned int b) {
                    return (nodes[a].position - first.position) * tangent <
                           (nodes[b].position - first.position) * tangent;
                  });
        std::vector<double> weights;
        std::vector<double> indicators;
        for (const unsigned int p : members[j])
          {
            const JointResponse<2> &response = responses[p];
            const double            weight   = nodes[p].weight;
            JointNodeSample         sample;
            // Distance along the joint surface (the polyline through the
            // nodes), not the projection on the straight part: on a
            // fillet the two differ by up to pi/2, and the contact end is
            // interpolated along the surface.
            sample.arc_position =
              report.profile.empty() ?
                0. :
                report.profile.back().arc_position +
                  nodes[p].position.distance(report.profile.back().position);
            sample.position        = nodes[p].position;
            sample.normal_traction = response.normal_traction;
            sample.tangential_traction =
              response.tangential_traction * tangent_of(nodes[p].normal);
            sample.gap            = response.gap;
            sample.state          = response.state;
            sample.exact_traction = response.exact_traction;
            report.profile.push_back(sample);
            weights.push_back(weight);
            indicators.push_back(contact_indicator(response));
            // The joint's forces are the components of the resultant
            // along the reference normal and tangent, so that the joint
            // tables balance each block also where fillet nodes turn
            // their own normals away (a scalar sum of their tractions
            // does not). The force density is -t_n n + t_t, as
            // JointResponse::force_density: compression acts along -n.
            const dealii::Tensor<1, 2> force_density =
              -response.normal_traction * nodes[p].normal +
              response.tangential_traction;
            report.normal_force -= weight * (force_density * normal);
            report.shear_force += weight * (force_density * tangent);
          }
        std::tie(report.closed_length, report.closed_length_uncertainty) =
          interpolated_closed_length(report.profile, weights, indicators);
        std::vector<JointState> states;
        for (const auto &sample : report.profile)
          states.push_back(sample.state);
        report.counts = count_states(states);
        report.mean_normal_stress =
          report.closed_length > 0. ?
            report.normal_force / report.closed_length :
            0.;
        add_peak_stresses(report, weights);
      }
    return reports;
  }

  double
  largest_overlap(const std::vector<JointReport> &joints)
  {
    double largest = 0.;
    for (const auto &joint : joints)
      for (const auto &sample : joint.profile)
        largest = std::max(largest, -sample.gap);
    return largest;
  }
} // namespace FloorBlock::Postprocess
