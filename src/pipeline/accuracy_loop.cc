#include <pipeline/accuracy_loop.h>
#include <pipeline/error_estimate.h>
#include <pipeline/target_loop.h>
#include <scene/rigid_inputs.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace FloorBlock::Pipeline
{
  namespace
  {
    using Parameters::TargetFigure;

    /** A Mesh/Target figures entry: its fem.json key and its estimate. */
    struct TargetField
    {
      TargetFigure                              figure;
      const char                               *key;
      Output::FigureError Output::JointErrors::*error;
    };

    constexpr TargetField target_fields[] = {
      {TargetFigure::normal_force, "normal_force_N_per_m",
       &Output::JointErrors::normal_force},
      {TargetFigure::contact_length, "contact_length_m",
       &Output::JointErrors::contact_length},
      {TargetFigure::sigma_max, "sigma_max_Pa", &Output::JointErrors::sigma_max},
      {TargetFigure::sigma_max_averaged, "sigma_max_averaged_Pa",
       &Output::JointErrors::sigma_max_averaged}};

    const TargetField &
    field_of(const TargetFigure figure)
    {
      for (const TargetField &field : target_fields)
        if (field.figure == figure)
          return field;
      throw std::logic_error("unknown target figure");
    }
  } // namespace

  std::string
  target_figure_key(const TargetFigure figure)
  {
    return field_of(figure).key;
  }

  std::optional<double>
  worst_target_error(const Output::FemErrorEstimate              &estimate,
                     const std::string                           &joint,
                     const std::vector<Parameters::TargetFigure> &figures)
  {
    if (!estimate.available || estimate.joints.count(joint) == 0)
      return std::nullopt;
    const Output::JointErrors &errors = estimate.joints.at(joint);
    double                     worst  = 0.;
    for (const TargetFigure figure : figures)
      {
        const Output::FigureError &error = errors.*field_of(figure).error;
        const double               relative =
          error.relative_error ? *error.relative_error :
          error.absolute_error == 0. ?
                                 0. :
                                 std::numeric_limits<double>::infinity();
        worst = std::max(worst, relative);
      }
    return worst;
  }

  TargetedSolve
  solve_to_target(const Parameters::ScenarioParameters &scene,
                  const Output::ResultFolder           &folder)
  {
    if (Scene::uses_rigid_blocks(scene) ||
        !scene.solver.estimate_error_by_refined_solve)
      {
        TargetedSolve solve{solve_scene(scene, folder), std::nullopt};
        solve.estimate = estimate_error(scene, solve.outcome, folder);
        return solve;
      }
    TargetLoop loop(scene, folder, folder);
    while (!loop.finished())
      loop.step();
    auto [outcome, estimate] = loop.finish();
    return {std::move(outcome), std::move(estimate)};
  }
} // namespace FloorBlock::Pipeline
