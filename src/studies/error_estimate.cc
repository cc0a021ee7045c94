#include <fmt/format.h>
#include <studies/convergence_ladder.h>
#include <studies/error_estimate.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace FloorBlock::Studies
{
  namespace
  {
    using Figure = double             Contact::JointReport::*;
    using Error  = Output::FigureError Output::JointErrors::*;

    /** A figure of JointReport and where its estimate goes. */
    struct EstimatedFigure
    {
      Figure figure;
      Error  error;
      /** The reported solve's own uncertainty of the figure, added; or null. */
      Figure own_uncertainty;
    };

    const EstimatedFigure estimated_figures[] = {
      {&Contact::JointReport::normal_force,
       &Output::JointErrors::normal_force,
       nullptr},
      // A contact end moves with the active set, not smoothly, so the
      // refined difference can be small by chance; the ends' location
      // uncertainty is added (see error_from_refined_difference).
      {&Contact::JointReport::closed_length,
       &Output::JointErrors::contact_length,
       &Contact::JointReport::closed_length_uncertainty},
      {&Contact::JointReport::peak_normal_stress,
       &Output::JointErrors::sigma_max,
       nullptr},
      {&Contact::JointReport::averaged_peak_normal_stress,
       &Output::JointErrors::sigma_max_averaged,
       nullptr}};

    std::vector<Contact::JointReport>
    final_joints(const Pipeline::FemOutcome &outcome)
    {
      return outcome.result.increments.empty() ?
               std::vector<Contact::JointReport>() :
               outcome.result.increments.back().joints;
    }

    std::optional<double>
    relative_to(const double absolute_error, const double refined_value)
    {
      return refined_value != 0. ?
               std::optional<double>(absolute_error / std::abs(refined_value)) :
               std::nullopt;
    }

    using CornerFactor = double                Safety::CornerSafety::*;
    using CornerError  = Output::FigureError Output::CornerErrors::*;

    /** The safety factors of a corner and where their estimates go. */
    const std::pair<CornerFactor, CornerError> estimated_corner_factors[] = {
      {&Safety::CornerSafety::point_factor, &Output::CornerErrors::point_factor},
      {&Safety::CornerSafety::line_factor, &Output::CornerErrors::line_factor},
      {&Safety::CornerSafety::area_factor, &Output::CornerErrors::area_factor}};

    /** The corner of @p corners with @p label, if its path is resolved. */
    const Safety::CornerSafety *
    resolved_corner(const std::vector<Safety::CornerSafety> &corners,
                    const std::string                       &label)
    {
      for (const Safety::CornerSafety &corner : corners)
        if (corner.path.label() == label)
          return corner.resolved() ? &corner : nullptr;
      return nullptr;
    }

    /**
     * The corners' safety factors: a factor is a function of the stress
     * at and near L/2, which converges like the stresses (to first order
     * with FE degree 1 where the path's cells are L/16), so the same
     * factor per difference as the joints' figures. Only corners that both
     * solves resolve: elsewhere a factor is a cell's value, no figure.
     */
    void
    estimate_corner_factors(Output::FemErrorEstimate   &estimate,
                            const Pipeline::FemOutcome &coarse,
                            const Pipeline::FemOutcome &fine,
                            const double                factor)
    {
      const bool coarse_reported =
        estimate.reported_solve == Output::ReportedSolve::coarse;
      for (const Safety::CornerSafety &coarse_corner :
           coarse.report.corner_safety)
        {
          const std::string label = coarse_corner.path.label();
          const Safety::CornerSafety *fine_corner =
            resolved_corner(fine.report.corner_safety, label);
          if (!coarse_corner.resolved() || fine_corner == nullptr)
            continue;
          Output::CornerErrors &errors = estimate.corners[label];
          for (const auto &[value, error] : estimated_corner_factors)
            {
              Output::FigureError &entry = errors.*error;
              entry.coarse_value         = coarse_corner.*value;
              entry.refined_value        = (*fine_corner).*value;
              entry.value =
                coarse_reported ? entry.coarse_value : entry.refined_value;
              entry.absolute_error =
                factor * std::abs(entry.coarse_value - entry.refined_value);
              entry.relative_error =
                relative_to(entry.absolute_error, entry.refined_value);
            }
        }
    }
  } // namespace

  Parameters::ScenarioParameters
  refined_scene(Parameters::ScenarioParameters scene)
  {
    // The next level of `converge`'s uniform ladder, so that `run` and
    // `converge` mean the same by "refined": every cell halved, including
    // those near the end of the contact zone, away from the corners.
    scene = uniform_level_scene(scene, 1);
    // The rigid-block model's only discretisation: points along each joint.
    scene.model.rigid_points_per_joint *= 2;
    return scene;
  }

  Output::FemErrorEstimate
  refined_solve_error(const Pipeline::FemOutcome &coarse,
                      const Pipeline::FemOutcome &fine,
                      const Output::ReportedSolve reported)
  {
    Output::FemErrorEstimate estimate;
    estimate.reported_solve = reported;
    const double factor     = error_per_difference(reported);
    // The factor is printed from the constant, so text and value agree.
    estimate.method = fmt::format(
      "{}: {} times the difference to {}: first-order Richardson with the "
      "two-grid safety factor 3; contact lengths add their ends' location "
      "uncertainty (two end rules)",
      reported == Output::ReportedSolve::coarse ?
        "figures of the coarse solve" :
        "figures of the refined solve",
      factor,
      coarse.report.model == "rigid blocks" ?
        "one solve with twice the points per joint" :
        "a solve on the same mesh with every cell halved (nested)");
    // A refined solve that stopped early describes a different load state:
    // comparing with it would be no error estimate at all.
    if (!fine.converged)
      {
        estimate.status_text =
          "the refined solve did not converge: " + fine.report.status_text;
        return estimate;
      }
    estimate.available        = true;
    estimate.refined_n_dofs   = fine.result.n_dofs;
    estimate.refined_status   = fine.report.status;
    const auto  coarse_joints = final_joints(coarse);
    const auto  fine_joints   = final_joints(fine);
    const auto &reported_joints =
      reported == Output::ReportedSolve::coarse ? coarse_joints : fine_joints;
    for (std::size_t k = 0; k < coarse_joints.size() && k < fine_joints.size();
         ++k)
      {
        Output::JointErrors &errors = estimate.joints[coarse_joints[k].name];
        for (const auto &[figure, error, own_uncertainty] : estimated_figures)
          {
            const double coarse_value = coarse_joints[k].*figure;
            const double fine_value   = fine_joints[k].*figure;
            const double estimate =
              factor * std::abs(coarse_value - fine_value) +
              (own_uncertainty ? reported_joints[k].*own_uncertainty : 0.);
            Output::FigureError &entry = errors.*error;
            entry.value                = reported_joints[k].*figure;
            entry.refined_value        = fine_value;
            entry.absolute_error       = estimate;
            entry.relative_error       = relative_to(estimate, fine_value);
            entry.coarse_value         = coarse_value;
          }
      }
    estimate_corner_factors(estimate, coarse, fine, factor);
    return estimate;
  }

  namespace
  {
    /**
     * Calls @p widening(entry, other_value) for every figure of every
     * joint and every corner factor that @p estimate and the converged
     * solve @p other share (a corner only where @p other resolves it); it
     * returns the error the entry should have at least. Raises the
     * entry's error to it and returns whether any was raised.
     */
    template <typename Widening>
    bool
    widen_against(Output::FemErrorEstimate   &estimate,
                  const Pipeline::FemOutcome &other,
                  const Widening             &widening)
    {
      if (!estimate.available || !other.converged)
        return false;
      bool       widened = false;
      const auto raise   = [&](Output::FigureError &entry, const double value) {
        const double least = widening(entry, value);
        if (least > entry.absolute_error)
          {
            entry.absolute_error = least;
            entry.relative_error = relative_to(least, entry.refined_value);
            widened              = true;
          }
      };
      for (const Contact::JointReport &joint : final_joints(other))
        {
          const auto errors = estimate.joints.find(joint.name);
          if (errors != estimate.joints.end())
            for (const auto &[figure, error, own_uncertainty] :
                 estimated_figures)
              raise(errors->second.*error, joint.*figure);
        }
      for (const Safety::CornerSafety &corner : other.report.corner_safety)
        {
          const auto errors = estimate.corners.find(corner.path.label());
          if (errors != estimate.corners.end() && corner.resolved())
            for (const auto &[value, error] : estimated_corner_factors)
              raise(errors->second.*error, corner.*value);
        }
      return widened;
    }
  } // namespace

  void
  widen_where_oscillating(Output::FemErrorEstimate   &estimate,
                          const Pipeline::FemOutcome &previous)
  {
    const auto range_if_reversed = [](Output::FigureError &entry,
                                      const double         previous_value) {
      const double step  = entry.coarse_value - previous_value;
      const double check = entry.refined_value - entry.coarse_value;
      if (!(step * check < 0.))
        return 0.; // monotone (or a zero step): the pair's estimate holds
      entry.oscillating = true;
      return std::max(
               {previous_value, entry.coarse_value, entry.refined_value}) -
             std::min(
               {previous_value, entry.coarse_value, entry.refined_value});
    };
    if (widen_against(estimate, previous, range_if_reversed))
      estimate.method += "; where the check reversed the previous level's "
                         "change, at least the range of the three values";
  }

  void
  widen_to_contain(Output::FemErrorEstimate   &estimate,
                   const Pipeline::FemOutcome &next,
                   const unsigned int          next_level)
  {
    const auto distance = [](Output::FigureError &entry,
                             const double         next_value) {
      entry.next_level_value = next_value;
      return std::abs(next_value - entry.value);
    };
    if (widen_against(estimate, next, distance))
      estimate.method += fmt::format(
        "; where level {} lies outside the bracket, at least the distance "
        "to it",
        next_level);
  }

  std::optional<Output::FemErrorEstimate>
  estimate_error(const Parameters::ScenarioParameters &scene,
                 const Pipeline::FemOutcome           &coarse,
                 const Output::ResultFolder           &folder)
  {
    if (!scene.solver.estimate_error_by_refined_solve || !coarse.converged)
      return std::nullopt;
    return refined_solve_error(
      coarse,
      Pipeline::solve_scene(refined_scene(scene),
                            Output::ResultFolder(folder.path_of("refined"))));
  }
} // namespace FloorBlock::Studies
