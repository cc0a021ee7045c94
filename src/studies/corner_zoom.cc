#include <contact/contact_solver.h>
#include <corner/side_mean_pressure.h>
#include <geometry/ids.h>
#include <material/elastic_law.h>
#include <pipeline/closed_form_comparison.h>
#include <scene/closed_forms.h>
#include <scene/mesh_sizing.h>

#include <deal.II/base/timer.h>

#include <studies/corner_zoom.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace FloorBlock::Studies
{
  double
  peak_change(const std::vector<ZoomLevel> &levels, const std::size_t k)
  {
    const double before = levels[k - 1].profile.peak_traction;
    return before != 0. ?
             std::abs(levels[k].profile.peak_traction / before - 1.) :
             1.;
  }

  bool
  peak_settled(const std::vector<ZoomLevel> &levels, const double tolerance)
  {
    const std::size_t n = levels.size();
    return n >= 3 && peak_change(levels, n - 1) <= tolerance &&
           peak_change(levels, n - 2) <= tolerance;
  }

  CornerZoom::CornerZoom(const Parameters::ScenarioParameters &scene,
                         const Corner::CornerSite             &site)
    : scene(scene)
    , site(site)
    , adaptive(scene, Studies::bounded_refinement({}, scene), 0.)
    , corner_size(scene.mesh.corner_size *
                  std::exp2(-double(Scene::global_refinements(scene))))
  {}

  const std::vector<ZoomLevel> &
  CornerZoom::levels() const
  {
    return done;
  }

  namespace
  {
    /**
     * The value of each face whose two vertices are both profile samples
     * (one joint side's nodes; coincident sides share positions, mirrored
     * fillets do not), at the mean of their distances from the contact's
     * end, to 1e-12 m (the zoom's cells stay above 3e-7 m); sorted by
     * distance.
     */
    std::vector<Analytic::RadialSample>
    matched_values(const Corner::CornerProfile          &profile,
                   const std::vector<Corner::FaceValue> &values)
    {
      constexpr double reach       = 1e-12;
      const auto       distance_of = [&](const dealii::Point<2> &at) {
        for (std::size_t k = 0; k < profile.samples.size(); ++k)
          if (profile.sample_positions[k].distance(at) <= reach)
            return profile.samples[k].distance;
        return -1.;
      };
      std::vector<Analytic::RadialSample> matched;
      for (const Corner::FaceValue &value : values)
        {
          const double first = distance_of(value.first);
          if (first < 0.)
            continue;
          const double second = distance_of(value.second);
          if (second >= 0.)
            matched.push_back({0.5 * (first + second), value.value});
        }
      std::sort(matched.begin(),
                matched.end(),
                [](const auto &a, const auto &b) {
                  return a.distance < b.distance;
                });
      return matched;
    }
  } // namespace

  bool
  CornerZoom::can_refine() const
  {
    const double next_size = corner_size * std::exp2(-double(done.size()));
    return next_size >=
           smallest_zoom_cell *
             std::min(scene.geometry.block_width, scene.geometry.block_height);
  }

  std::vector<Geometry::LocalSize>
  CornerZoom::window(const double size) const
  {
    const Corner::CornerProfile &last = done.back().profile;
    const double                 zone_length =
      last.samples.empty() ? size : last.samples.back().distance;
    double from = 0., to = 0.; // "height" (arc towards the top), m
    if (last.kind == Corner::CornerContactKind::edge_in_fillet)
      {
        const double reach = std::max(last.edge_beyond_corner, 4. * size);
        from               = last.corner_arc - reach;
        to                 = last.edge_arc + reach;
      }
    else
      {
        const double reach = std::max(0.1 * zone_length, 4. * size);
        from               = last.edge_arc - reach;
        to                 = last.edge_arc + reach;
      }

    // Points every `size` along the polyline of the joint side's nodes.
    std::vector<Contact::JointNodeSample> nodes = last_joint_profile;
    std::sort(nodes.begin(), nodes.end(), [](const auto &a, const auto &b) {
      return a.arc_position < b.arc_position;
    });
    const double up =
      nodes.back().position[1] >= nodes.front().position[1] ? 1. : -1.;
    std::vector<Geometry::LocalSize> points;
    for (std::size_t k = 1; k < nodes.size(); ++k)
      {
        const double h0 = up * nodes[k - 1].arc_position;
        const double h1 = up * nodes[k].arc_position;
        const double lo = std::max(std::min(h0, h1), from);
        const double hi = std::min(std::max(h0, h1), to);
        if (lo > hi || h0 == h1)
          continue;
        const unsigned int n_points =
          1 + static_cast<unsigned int>(std::ceil((hi - lo) / size));
        for (unsigned int i = 0; i <= n_points; ++i)
          {
            const double h = lo + (hi - lo) * i / n_points;
            const double w = (h - h0) / (h1 - h0);
            const auto  &a = nodes[k - 1].position, &b = nodes[k].position;
            points.push_back(
              {{a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1])}, size});
          }
      }
    return points;
  }

  std::optional<ZoomLevel>
  CornerZoom::next(const Output::ResultFolder &folder)
  {
    dealii::Timer clock;
    ZoomLevel     record;
    record.level = static_cast<unsigned int>(done.size());
    Pipeline::FemOutcome outcome;
    // The mean pressure on both joint sides while the solution exists.
    std::vector<Corner::FaceValue> side_pressures;
    Pipeline::SolveExtras          extras;
    extras.inspect = [&](const Contact::ContactSolver<2> &solver) {
      const auto law = Material::ElasticLaw<2>::from_youngs_poisson(
        scene.material.youngs_modulus(), scene.material.poissons_ratio());
      for (const auto side :
           {Geometry::Ids::vertical_joint_free_side(site.joint),
            Geometry::Ids::vertical_joint_face_side(site.joint)})
        {
          const auto values = Corner::mean_pressure_on_side(solver.space(),
                                                            solver.solution(),
                                                            side,
                                                            law);
          side_pressures.insert(side_pressures.end(),
                                values.begin(),
                                values.end());
        }
    };
    if (done.empty())
      {
        record.requested_size = corner_size;
        outcome               = adaptive.solve_next(folder, false, extras);
      }
    else
      {
        record.requested_size = corner_size * std::exp2(-double(record.level));
        outcome = adaptive.solve_refined_toward(window(record.requested_size),
                                                zoom_growth_rate,
                                                folder,
                                                false,
                                                extras);
      }
    if (!outcome.converged || outcome.result.increments.empty())
      return std::nullopt;
    record.wall_time = clock.wall_time();
    record.n_dofs    = outcome.result.n_dofs;
    bool found       = false;
    for (const auto &joint : outcome.result.increments.back().joints)
      if (joint.name == site.joint_name)
        {
          record.profile              = Corner::corner_profile(joint, site);
          record.normal_force         = joint.normal_force;
          record.closed_length        = joint.closed_length;
          record.peak_normal_stress   = joint.peak_normal_stress;
          record.averaged_peak_stress = joint.averaged_peak_normal_stress;
          record.averaging_length     = joint.averaging_length;
          last_joint_profile          = joint.profile;
          found                       = true;
        }
    if (!found)
      throw std::logic_error("CornerZoom: no joint '" + site.joint_name +
                             "' in the solution");
    record.invariant_samples = matched_values(record.profile, side_pressures);
    for (const auto &joint :
         Pipeline::compare_with_closed_forms(
           outcome, Scene::evaluate_closed_forms(scene), scene)
           .final_joints)
      if (joint.joint == site.joint)
        {
          record.relative_rotation = joint.contact.relative_rotation;
          record.closed_form_contact_length =
            joint.contact.closed_form.contact_length;
          record.closed_form_peak = joint.contact.closed_form.max_stress;
        }
    done.push_back(record);
    return record;
  }
} // namespace FloorBlock::Studies
