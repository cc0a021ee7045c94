#include <scene/mesh_sizing.h>
#include <scene/rigid_inputs.h>

#include <fmt/format.h>
#include <studies/accuracy_loop.h>
#include <studies/degree_race.h>
#include <studies/error_estimate.h>
#include <studies/target_loop.h>

#include <algorithm>
#include <iostream>
#include <limits>
#include <stdexcept>

namespace FloorBlock::Studies
{
  namespace
  {
    using Parameters::TargetFigure;

    /** A Mesh/Target figures entry: its fem.json key and its estimate. */
    struct TargetField
    {
      TargetFigure        figure;
      const char         *key;
      Output::FigureError Output::JointErrors::*error;
    };

    constexpr TargetField target_fields[] = {
      {TargetFigure::normal_force,
       "normal_force_N_per_m",
       &Output::JointErrors::normal_force},
      {TargetFigure::contact_length,
       "contact_length_m",
       &Output::JointErrors::contact_length},
      {TargetFigure::sigma_max,
       "sigma_max_Pa",
       &Output::JointErrors::sigma_max},
      {TargetFigure::sigma_max_averaged,
       "sigma_max_averaged_Pa",
       &Output::JointErrors::sigma_max_averaged}};

    const TargetField &
    field_of(const TargetFigure figure)
    {
      for (const TargetField &field : target_fields)
        if (field.figure == figure)
          return field;
      throw std::logic_error("unknown target figure");
    }

    /**
     * Why degree 2 joins, in words that agree with what degree 1's loop
     * printed: its level-0 pair missed the target, or met it and the
     * confirming level disagreed, or the loop stopped.
     */
    std::string
    degree_2_join_reason(const TargetLoop &degree_1)
    {
      const Output::AccuracyTarget &record = degree_1.record();
      if (record.confirming_level)
        return fmt::format("FE degree 1's level {} did not confirm the "
                           "target its level {} met",
                           *record.confirming_level,
                           record.reported_level);
      if (degree_1.finished())
        return "FE degree 1's loop stopped: " + record.stop_reason;
      return "FE degree 1's level 0 did not meet the target";
    }

    /**
     * Solver/FE degree = auto: degree 1's and degree 2's loops take turns
     * (next_race_turn()); the winner's solve is reported, the other
     * loop's record is kept in the estimate (AccuracyTarget::other_degrees).
     */
    TargetedSolve
    race_fe_degrees(const Parameters::ScenarioParameters &scene,
                    const Output::ResultFolder           &folder)
    {
      Parameters::ScenarioParameters degree_2_scene = scene;
      degree_2_scene.solver.fe_degree               = 2;
      TargetLoop                degree_1(scene, folder, folder);
      std::optional<TargetLoop> degree_2;
      const auto                degree_2_state = [&degree_2]() {
        return degree_2 ? degree_2->racer_state() : RacerState();
      };
      for (RaceTurn turn;
           (turn = next_race_turn(degree_1.racer_state(), degree_2_state())) !=
           RaceTurn::over;)
        if (turn == RaceTurn::degree_1)
          degree_1.step();
        else
          {
            if (!degree_2)
              {
                std::cout << "accuracy: " << degree_2_join_reason(degree_1)
                          << "; FE degree 2 joins (Solver/FE degree = auto), "
                             "the loop with less time spent solving next"
                          << std::endl;
                degree_2.emplace(degree_2_scene,
                                 Output::ResultFolder(
                                   folder.path_of("fe_degree_2")),
                                 folder,
                                 false);
              }
            degree_2->step();
          }
      // The budget is shared: once one loop ran out of it, so did the
      // other.
      TargetLoop *const out_of_time =
        degree_1.racer_state().out_of_time              ? &degree_1 :
        degree_2 && degree_2->racer_state().out_of_time ? &*degree_2 :
                                                          nullptr;
      TargetLoop *const other = out_of_time == &degree_1 ?
                                  (degree_2 ? &*degree_2 : nullptr) :
                                  &degree_1;
      if (out_of_time && other)
        other->abandon(fmt::format("in FE degree {}'s loop, {}",
                                   out_of_time->record().fe_degree,
                                   out_of_time->record().stop_reason));
      const RacerState   state_1 = degree_1.racer_state();
      const RacerState   state_2 = degree_2_state();
      const unsigned int winner  = race_winner(state_1, state_2);
      TargetLoop        &won     = winner == 1 ? degree_1 : *degree_2;
      TargetLoop *const  lost =
        winner == 1 ? (degree_2 ? &*degree_2 : nullptr) : &degree_1;
      std::string choice;
      if (!degree_2 && degree_1.met())
        choice = "auto: FE degree 1's level 0 met the target, which no "
                 "degree-2 solve on the same mesh could do sooner";
      else if (!degree_2)
        choice = "auto: FE degree 2 did not join, FE degree 1's loop "
                 "stopped: " +
                 degree_1.record().stop_reason;
      else
        {
          if (won.met())
            lost->abandon(
              fmt::format("FE degree {} met the target first", winner));
          choice = fmt::format(
            "auto: FE degrees 1 and 2 took turns; degree {} {} after {:.1f} "
            "s of its own solves (degree {}: {:.1f} s, {})",
            winner,
            won.met() ? "met the target first" :
                        "has the smaller error estimate, neither met it",
            won.time_spent(),
            winner == 1 ? 2 : 1,
            lost->time_spent(),
            lost->record().stop_reason);
        }
      std::cout << "accuracy: " << choice << std::endl;
      auto [outcome, estimate] = won.finish();
      if (estimate && estimate->target)
        {
          estimate->target->fe_degree_choice = choice;
          if (lost)
            estimate->target->other_degrees.push_back(lost->record());
        }
      return {std::move(outcome), std::move(estimate)};
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
          error.relative_error       ? *error.relative_error :
                        error.absolute_error == 0. ? 0. :
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
        TargetedSolve solve{Pipeline::solve_scene(scene, folder), std::nullopt};
        solve.estimate = estimate_error(scene, solve.outcome, folder);
        return solve;
      }
    // With exact contact the displacement is not smooth where a contact
    // zone ends and at the corners, so degree 2 converges no faster per
    // DoF than degree 1 there, and each of its checks has four times the
    // DoFs of degree 1's. On the default scene with the rigid law degree
    // 2's loop takes two thirds of a race's time and does not meet the
    // target (results/FINDINGS.md, section 7).
    if (scene.solver.choose_fe_degree && !Scene::contact_is_exact(scene))
      return race_fe_degrees(scene, folder);
    const std::string choice =
      scene.solver.choose_fe_degree ?
        std::string("auto: FE degree 1 alone, because the joints act as "
                    "exact contact (the rigid law, or E/kn below the corner "
                    "rounding radius), where degree 2 converges no faster") :
        fmt::format("Solver/FE degree = {}", scene.solver.fe_degree);
    if (scene.solver.choose_fe_degree)
      std::cout << "accuracy: " << choice << std::endl;
    TargetLoop loop(scene, folder, folder);
    while (!loop.finished())
      loop.step();
    auto [outcome, estimate] = loop.finish();
    if (estimate && estimate->target)
      estimate->target->fe_degree_choice = choice;
    return {std::move(outcome), std::move(estimate)};
  }
} // namespace FloorBlock::Studies
