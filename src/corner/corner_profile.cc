#include <corner/corner_profile.h>

#include <postprocess/joint_report.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace FloorBlock::Corner
{
  const char *
  to_string(const CornerContactKind kind)
  {
    switch (kind)
      {
        case CornerContactKind::edge_in_fillet:
          return "edge in fillet";
        case CornerContactKind::reaches_corner:
          return "reaches corner";
        case CornerContactKind::open_at_corner:
          return "open at corner";
      }
    return "?";
  }

  CornerProfile
  corner_profile(const Contact::JointReport &joint, const CornerSite &site)
  {
    using Contact::JointState;
    std::vector<Contact::JointNodeSample> nodes = joint.profile;
    if (nodes.size() < 3)
      throw std::runtime_error("corner_profile: joint '" + joint.name +
                               "' has fewer than 3 nodes");
    std::sort(nodes.begin(), nodes.end(), [](const auto &a, const auto &b) {
      return a.arc_position < b.arc_position;
    });
    // "Up" is along increasing arc if the last node lies higher.
    const double up =
      nodes.back().position[1] >= nodes.front().position[1] ? 1. : -1.;
    if (up < 0.)
      std::reverse(nodes.begin(), nodes.end());
    const auto height = [&](const Contact::JointNodeSample &node) {
      return up * node.arc_position;
    };

    CornerProfile profile;
    // The corner: the node nearest the site's corner point.
    const auto nearest =
      std::min_element(nodes.begin(),
                       nodes.end(),
                       [&](const auto &a, const auto &b) {
                         return std::hypot(a.position[0] - site.corner.x,
                                           a.position[1] - site.corner.y) <
                                std::hypot(b.position[0] - site.corner.x,
                                           b.position[1] - site.corner.y);
                       });
    profile.corner_arc = height(*nearest);

    int top_closed = -1;
    for (int k = static_cast<int>(nodes.size()) - 1; k >= 0; --k)
      if (nodes[k].state != JointState::open)
        {
          top_closed = k;
          break;
        }
    if (top_closed < 0)
      throw std::runtime_error("corner_profile: joint '" + joint.name +
                               "' is open everywhere");
    const auto &closed = nodes[top_closed];
    profile.edge_state = closed.state;
    profile.edge_traction_ratio =
      closed.normal_traction != 0. ?
        closed.tangential_traction / closed.normal_traction :
        0.;
    if (top_closed + 1 == static_cast<int>(nodes.size()))
      {
        profile.kind         = CornerContactKind::reaches_corner;
        profile.edge_arc     = height(closed);
        profile.edge_spacing = height(closed) - height(nodes[top_closed - 1]);
      }
    else
      {
        const double s_c     = height(closed);
        const double segment = height(nodes[top_closed + 1]) - s_c;
        double       beyond  = 0.;
        if (top_closed > 0 && nodes[top_closed - 1].state != JointState::open)
          {
            const double p_c = std::max(0., closed.normal_traction);
            const double p_b = nodes[top_closed - 1].normal_traction;
            if (p_b > p_c)
              beyond =
                std::min(segment,
                         Postprocess::square_root_edge_extent(
                           p_c, p_b, s_c - height(nodes[top_closed - 1])));
          }
        profile.edge_arc     = s_c + beyond;
        profile.edge_spacing = segment;
        // A zone that reaches the fillet's start ends in the fillet: on a
        // coarse mesh its end sits on the start node itself.
        const double round_off = 1e-9 * std::abs(segment);
        profile.kind = profile.edge_arc >= profile.corner_arc - round_off ?
                         CornerContactKind::edge_in_fillet :
                         CornerContactKind::open_at_corner;
      }
    profile.edge_beyond_corner = profile.edge_arc - profile.corner_arc;

    for (int k = top_closed; k >= 0 && nodes[k].state != JointState::open; --k)
      {
        const double distance = profile.edge_arc - height(nodes[k]);
        if (nodes[k].normal_traction > profile.peak_traction)
          {
            profile.peak_traction = nodes[k].normal_traction;
            profile.peak_distance = distance;
          }
        if (distance > 0.)
          {
            profile.samples.push_back({distance, nodes[k].normal_traction});
            profile.sample_positions.push_back(nodes[k].position);
          }
      }
    return profile;
  }
} // namespace FloorBlock::Corner
