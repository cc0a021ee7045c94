#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/error_estimator.h>

#include <refinement/size_targets.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace FloorBlock::Refinement
{
  namespace
  {
    Geometry::Point2
    point2(const dealii::Point<2> &point)
    {
      return {point[0], point[1]};
    }

    bool
    is_closed(const Contact::JointState state)
    {
      return state != Contact::JointState::open;
    }

    double
    largest_traction_jump(const std::vector<Contact::JointReport> &joints)
    {
      double largest = 0.;
      for (const auto &joint : joints)
        for (std::size_t k = 0; k + 1 < joint.profile.size(); ++k)
          largest = std::max(largest,
                             std::abs(joint.profile[k + 1].normal_traction -
                                      joint.profile[k].normal_traction));
      return largest;
    }
  } // namespace

  std::vector<Geometry::LocalSize>
  joint_size_targets(const std::vector<Contact::JointReport> &joints,
                     const RefinementSettings                &settings)
  {
    const double jump_threshold =
      settings.traction_jump_fraction * largest_traction_jump(joints);
    std::vector<Geometry::LocalSize> targets;
    for (const auto &joint : joints)
      {
        const auto &profile = joint.profile;
        if (profile.size() < 2)
          continue;
        const std::size_t n_segments = profile.size() - 1;
        // Per segment: 0 = not refined, else the divisor of its length.
        std::vector<double> divisor(n_segments, 0.);
        for (std::size_t k = 0; k < n_segments; ++k)
          {
            const double jump = std::abs(profile[k + 1].normal_traction -
                                         profile[k].normal_traction);
            // jump > 0 keeps a joint without any traction from being
            // marked everywhere when the threshold is 0.
            if (jump > 0. && jump >= jump_threshold)
              divisor[k] = std::max(divisor[k], 2.);
            // The end of a closed zone moves by up to a segment when the
            // mesh changes: its neighbours are refined with it, so that the
            // next level still finds the end inside the refined patch.
            if (is_closed(profile[k].state) != is_closed(profile[k + 1].state))
              for (std::size_t m = (k > 0 ? k - 1 : 0);
                   m <= std::min(k + 1, n_segments - 1);
                   ++m)
                divisor[m] = std::max(divisor[m], settings.zone_end_refinement);
          }
        for (std::size_t k = 0; k < n_segments; ++k)
          if (divisor[k] > 0.)
            {
              const double size =
                std::max(settings.smallest_size,
                         profile[k].position.distance(profile[k + 1].position) /
                           divisor[k]);
              targets.push_back({point2(profile[k].position), size});
              targets.push_back({point2(profile[k + 1].position), size});
            }
      }
    return targets;
  }

  double
  cell_size(const dealii::TriaAccessor<2, 2, 2> &cell)
  {
    return std::sqrt(cell.measure());
  }

  dealii::Vector<float>
  kelly_indicator(const Fem::FeSpace<2>                       &space,
                  const dealii::TrilinosWrappers::MPI::Vector &solution)
  {
    const auto &dofs = space.dof_handler();
    // A serial copy: the estimator reads neighbour values across every
    // face, and the solver's vector is one rank's non-ghosted vector.
    const dealii::Vector<double> displacement(solution);
    dealii::Vector<float> indicator(dofs.get_triangulation().n_active_cells());
    dealii::KellyErrorEstimator<2>::estimate(space.mapping(),
                                             dofs,
                                             dealii::QGauss<1>(space.degree() +
                                                               1),
                                             {},
                                             displacement,
                                             indicator);
    return indicator;
  }

  std::vector<Geometry::LocalSize>
  bulk_size_targets(const dealii::Triangulation<2> &triangulation,
                    const dealii::Vector<float>    &indicator,
                    const RefinementSettings       &settings)
  {
    std::vector<unsigned int> order(indicator.size());
    std::iota(order.begin(), order.end(), 0u);
    const std::size_t n_marked =
      std::min<std::size_t>(order.size(),
                            static_cast<std::size_t>(std::ceil(
                              settings.bulk_fraction * order.size())));
    std::partial_sort(order.begin(),
                      order.begin() + n_marked,
                      order.end(),
                      [&](const unsigned int a, const unsigned int b) {
                        return indicator[a] > indicator[b];
                      });
    std::vector<bool> marked(order.size(), false);
    for (std::size_t k = 0; k < n_marked; ++k)
      marked[order[k]] = indicator[order[k]] > 0.f;

    std::vector<Geometry::LocalSize> targets;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (marked[cell->active_cell_index()])
        targets.push_back(
          {point2(cell->center()),
           std::max(settings.smallest_size, cell_size(*cell) / 2.)});
    return targets;
  }

  void
  merge_size_requests(std::vector<Geometry::LocalSize> &requests,
                      std::vector<Geometry::LocalSize>  candidates,
                      const double                      growth_rate)
  {
    // Relative margin below which a candidate adds nothing (round-off of
    // the distance and size arithmetic). Units: 1.
    constexpr double redundancy_margin = 1e-9;
    std::sort(candidates.begin(),
              candidates.end(),
              [](const Geometry::LocalSize &a, const Geometry::LocalSize &b) {
                return a.size < b.size;
              });
    for (const auto &candidate : candidates)
      if (Geometry::local_size_at(requests, growth_rate, candidate.position) >
          candidate.size * (1. + redundancy_margin))
        requests.push_back(candidate);
  }
} // namespace FloorBlock::Refinement
