#include <geometry/assembly_description.h>
#include <geometry/body_outline.h>
#include <scene/assembly_inputs.h>
#include <scene/closed_forms.h>
#include <scene/floor_contact_problem.h>
#include <scene/mesh_sizing.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace FloorBlock::Scene
{
  namespace
  {
    /** Whether a segment is a straight vertical line: a vertical joint side. */
    bool
    is_vertical_line(const Geometry::Segment &segment)
    {
      const double length = std::hypot(segment.end.x - segment.start.x,
                                       segment.end.y - segment.start.y);
      return segment.kind == Geometry::SegmentKind::line && length > 0. &&
             std::abs(segment.end.x - segment.start.x) <= 1e-9 * length;
    }

    /**
     * Points of size @p size every @p size (m) from @p end towards
     * @p other, over @p reach (m) but not past @p other.
     */
    void
    add_zone_points(const Geometry::Point2           &end,
                    const Geometry::Point2           &other,
                    const double                      reach,
                    const double                      size,
                    std::vector<Geometry::LocalSize> &sizes)
    {
      const double length = std::hypot(other.x - end.x, other.y - end.y);
      const double extent = std::min(reach, length);
      const auto   n_steps =
        static_cast<unsigned int>(std::ceil(extent / size - 1e-9));
      for (unsigned int k = 0; k <= n_steps; ++k)
        {
          const double fraction = std::min(extent, k * size) / length;
          sizes.push_back({{end.x + fraction * (other.x - end.x),
                            end.y + fraction * (other.y - end.y)},
                           size});
        }
    }
    /**
     * Points of size @p size every @p size (m) along the joint's nodes from
     * arc position @p from to @p to, clipped to the joint, each placed by
     * linear interpolation between the nodes around it.
     */
    void
    add_profile_points(const std::vector<Contact::JointNodeSample> &profile,
                       const double                                 from,
                       const double                                 to,
                       const double                                 size,
                       std::vector<Geometry::LocalSize>            &sizes)
    {
      const double start = std::max(from, profile.front().arc_position);
      const double end   = std::min(to, profile.back().arc_position);
      const auto   n_steps =
        static_cast<unsigned int>(std::ceil((end - start) / size - 1e-9));
      for (unsigned int k = 0; k <= n_steps; ++k)
        {
          const double s = std::min(end, start + k * size);
          auto         after =
            std::upper_bound(profile.begin(),
                             profile.end(),
                             s,
                             [](const double                    value,
                                const Contact::JointNodeSample &node) {
                               return value < node.arc_position;
                             });
          if (after == profile.end())
            after = std::prev(profile.end());
          if (after == profile.begin())
            after = std::next(profile.begin());
          const auto  &a    = *std::prev(after);
          const auto  &b    = *after;
          const double span = b.arc_position - a.arc_position;
          const double t =
            span > 0. ? std::clamp((s - a.arc_position) / span, 0., 1.) : 0.;
          sizes.push_back(
            {{a.position[0] + t * (b.position[0] - a.position[0]),
              a.position[1] + t * (b.position[1] - a.position[1])},
             size});
        }
    }
  } // namespace

  std::optional<double>
  estimated_contact_length(const Parameters::ScenarioParameters &scene)
  {
    const ClosedForms closed = evaluate_closed_forms(scene);
    // Their contact length belongs to another scene: not an estimate of
    // this one's.
    if (!closed.scene_differences.empty())
      return std::nullopt;
    std::optional<double> shortest;
    for (const MechanismResult &mechanism : closed.mechanisms)
      {
        const Analytic::CornerContact &contact = mechanism.contact;
        const bool has_length = Analytic::has_contact_values(contact.status);
        if (!has_length || !std::isfinite(contact.contact_length) ||
            !(contact.contact_length > 0.))
          continue;
        const double length =
          std::min(contact.contact_length, scene.geometry.block_height);
        if (!shortest || length < *shortest)
          shortest = length;
      }
    return shortest;
  }

  const char *
  source_key(const ContactZoneSource source)
  {
    switch (source)
      {
        case ContactZoneSource::not_asked:
          return "not_asked";
        case ContactZoneSource::closed_form:
          return "closed_form";
        case ContactZoneSource::first_solve:
          return "first_solve";
        case ContactZoneSource::none:
          return "none";
      }
    return "none";
  }

  std::string
  describe(const ContactZoneSizing &sizing, const unsigned int cells_per_length)
  {
    const auto sized = [&](const char *from) {
      return fmt::format("contact zones sized from {}: c = {:.1f} mm, "
                         "cells of c/{}",
                         from,
                         sizing.contact_length * 1e3,
                         cells_per_length);
    };
    switch (sizing.source)
      {
        case ContactZoneSource::not_asked:
          return "no contact-zone sizing (Mesh/Cells per contact length "
                 "= 0)";
        case ContactZoneSource::closed_form:
          return sized("Eq. 6.51 (the face joint's closed-form contact "
                       "length)");
        case ContactZoneSource::first_solve:
          return sized("the FEM's first solve on the plain mesh (the "
                       "shortest computed vertical contact)");
        case ContactZoneSource::none:
          return "no contact-zone sizing: " + sizing.reason;
      }
    return {};
  }

  ContactZoneSizing
  closed_form_contact_zones(const Parameters::ScenarioParameters &scene)
  {
    const unsigned int n_cells = scene.mesh.cells_per_contact_length;
    if (n_cells == 0)
      return {};
    const std::optional<double> contact_length =
      estimated_contact_length(scene);
    if (!contact_length)
      return {ContactZoneSource::none,
              0.,
              "Eq. 6.51 gives no contact length for this scene",
              {}};
    ContactZoneSizing sizing{ContactZoneSource::closed_form,
                             *contact_length,
                             {},
                             {}};
    const double      size =
      std::max(*contact_length / n_cells, scene.mesh.corner_size);
    const double reach = contact_zone_reach * *contact_length;

    const Geometry::AssemblyOutline outline =
      Geometry::build_outline(assembly_description(scene));
    for (const Geometry::JointPair &pair : outline.joint_pairs)
      {
        const Geometry::Segment &side =
          outline.bodies[pair.master.body].segments[pair.master.segment];
        if (!is_vertical_line(side))
          continue;
        // Eq. 6.51's contact runs down the joint from floor level: the
        // upper end of the side (the fillet below the floor is not in it).
        const bool start_is_upper = side.start.y > side.end.y;
        add_zone_points(start_is_upper ? side.start : side.end,
                        start_is_upper ? side.end : side.start,
                        reach,
                        size,
                        sizing.sizes);
      }
    return sizing;
  }

  ContactZoneSizing
  computed_contact_zones(const Parameters::ScenarioParameters    &scene,
                         const std::vector<Contact::JointReport> &joints)
  {
    const unsigned int n_cells = scene.mesh.cells_per_contact_length;
    if (n_cells == 0)
      return {};
    ContactZoneSizing sizing{ContactZoneSource::first_solve, 0., {}, {}};
    for (const Contact::JointReport &joint : joints)
      {
        const auto &profile = joint.profile;
        if (profile.size() < 2 || !(joint.closed_length > 0.) ||
            !is_vertical_joint(joint.name))
          continue;
        const auto is_closed = [](const Contact::JointNodeSample &node) {
          return node.state != Contact::JointState::open;
        };
        const auto first =
          std::find_if(profile.begin(), profile.end(), is_closed);
        const auto last =
          std::find_if(profile.rbegin(), profile.rend(), is_closed);
        if (first == profile.end())
          continue;
        const double c      = joint.closed_length;
        const double size   = std::max(c / n_cells, scene.mesh.corner_size);
        const double margin = (contact_zone_reach - 1.) * c;
        add_profile_points(profile,
                           first->arc_position - margin,
                           last->arc_position + margin,
                           size,
                           sizing.sizes);
        if (sizing.contact_length == 0. || c < sizing.contact_length)
          sizing.contact_length = c;
      }
    if (sizing.sizes.empty())
      return {ContactZoneSource::none,
              0.,
              "Eq. 6.51 gives no contact length for this scene and the "
              "first solve closed no vertical joint",
              {}};
    return sizing;
  }

  double
  joint_compliance_length(const Parameters::ScenarioParameters &scene)
  {
    if (scene.joints.law == Contact::JointLawKind::rigid)
      return 0.;
    return scene.material.youngs_modulus() / scene.joints.normal_stiffness;
  }

  bool
  contact_is_exact(const Parameters::ScenarioParameters &scene)
  {
    const double length = joint_compliance_length(scene);
    return length == 0. || length < scene.geometry.corner_rounding_radius;
  }

  unsigned int
  global_refinements(const Parameters::ScenarioParameters &scene)
  {
    if (scene.mesh.global_refinements)
      return *scene.mesh.global_refinements;
    const double radius = scene.geometry.corner_rounding_radius;
    if (radius <= 0. || !contact_is_exact(scene))
      return 0;
    unsigned int n_halvings = 0;
    // 1e-9 relative: a corner size of exactly 2 r takes one halving.
    while (n_halvings < max_auto_global_refinements &&
           scene.mesh.corner_size * std::exp2(-double(n_halvings)) >
             radius * (1. + 1e-9))
      ++n_halvings;
    return n_halvings;
  }

  std::vector<Geometry::LocalSize>
  critical_distance_sizes(const Parameters::ScenarioParameters &scene)
  {
    const unsigned int n_cells = scene.mesh.cells_per_critical_distance;
    // The corner safety factors are read from 2D solves only; a 3D mesh
    // swept from this section would carry the fine corners along its
    // whole length for nothing.
    if (n_cells == 0 || scene.geometry.dimension == 3)
      return {};
    const double L    = scene.strength.critical_distance;
    const double size = std::max(L / n_cells,
                                 Geometry::min_relative_local_size *
                                   std::min(scene.geometry.block_width,
                                            scene.geometry.block_height));
    const double r    = scene.geometry.corner_rounding_radius;

    const Geometry::AssemblyOutline outline =
      Geometry::build_outline(assembly_description(scene));
    std::vector<Geometry::LocalSize> sizes;
    for (const Geometry::JointPair &pair : outline.joint_pairs)
      {
        const Geometry::Segment &side =
          outline.bodies[pair.master.body].segments[pair.master.segment];
        if (!is_vertical_line(side))
          continue;
        // The sharp corner: the joint line at the blocks' top.
        const Geometry::Point2 upper =
          side.start.y > side.end.y ? side.start : side.end;
        const Geometry::Point2 corner{upper.x, upper.y + r};
        for (const double direction : {+1., -1.})
          add_zone_points(corner,
                          {corner.x + direction * 2. * L, corner.y - 2. * L},
                          critical_distance_reach * L + r,
                          size,
                          sizes);
      }
    return sizes;
  }
} // namespace FloorBlock::Scene
