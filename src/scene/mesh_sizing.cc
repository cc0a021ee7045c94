#include <geometry/body_outline.h>
#include <scene/assembly_inputs.h>
#include <scene/closed_forms.h>
#include <scene/mesh_sizing.h>

#include <algorithm>
#include <cmath>

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
  } // namespace

  std::optional<double>
  estimated_contact_length(const Parameters::ScenarioParameters &scene)
  {
    std::optional<double> shortest;
    for (const MechanismResult &mechanism :
         evaluate_closed_forms(scene).mechanisms)
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

  std::vector<Geometry::LocalSize>
  contact_zone_sizes(const Parameters::ScenarioParameters &scene)
  {
    const unsigned int n_cells = scene.mesh.cells_per_contact_length;
    if (n_cells == 0)
      return {};
    const std::optional<double> contact_length =
      estimated_contact_length(scene);
    if (!contact_length)
      return {};
    const double size =
      std::max(*contact_length / n_cells, scene.mesh.corner_size);
    const double reach = contact_zone_reach * *contact_length;

    const Geometry::AssemblyOutline outline =
      Geometry::build_outline(assembly_description(scene));
    std::vector<Geometry::LocalSize> sizes;
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
                        sizes);
      }
    return sizes;
  }

  double
  joint_compliance_length(const Parameters::ScenarioParameters &scene)
  {
    if (scene.joints.law == Contact::JointLawKind::rigid)
      return 0.;
    return scene.material.youngs_modulus() / scene.joints.normal_stiffness;
  }

  unsigned int
  global_refinements(const Parameters::ScenarioParameters &scene)
  {
    if (scene.mesh.global_refinements)
      return *scene.mesh.global_refinements;
    const double radius = scene.geometry.corner_rounding_radius;
    if (radius <= 0. || joint_compliance_length(scene) >= radius)
      return 0;
    unsigned int n_halvings = 0;
    // 1e-9 relative: a corner size of exactly 2 r takes one halving.
    while (n_halvings < max_auto_global_refinements &&
           scene.mesh.corner_size * std::exp2(-double(n_halvings)) >
             radius * (1. + 1e-9))
      ++n_halvings;
    return n_halvings;
  }
} // namespace FloorBlock::Scene
