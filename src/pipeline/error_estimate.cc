#include <pipeline/convergence_ladder.h>
#include <pipeline/error_estimate.h>

#include <cmath>
#include <utility>
#include <vector>

namespace FloorBlock::Pipeline
{
  using nlohmann::json;

  Parameters::ScenarioParameters
  refined_scene(Parameters::ScenarioParameters scene)
  {
    // The next level of `converge`'s uniform ladder, so that `run` and
    // `converge` mean the same by "refined". The growth rate is refined
    // too: halving only Corner size and Far size leaves the cells near the
    // end of the contact zone, away from the corners, almost unchanged.
    scene = uniform_level_scene(scene, 1);
    // The rigid-block model's only discretisation: points along each joint.
    scene.model.rigid_points_per_joint *= 2;
    return scene;
  }

  json
  refined_solve_error(const FemOutcome &coarse, const FemOutcome &fine)
  {
    const std::string method =
      coarse.report.model == "rigid blocks" ?
        "difference to one solve with twice the points per joint" :
        "difference to a solve on the next uniform refinement level "
        "(all mesh sizes and the growth rate's excess over 1 halved)";
    // A refined solve that stopped early describes a different load state:
    // comparing with it would be no error estimate at all.
    if (!fine.converged)
      return {{"method", method},
              {"status", "unavailable"},
              {"status_text", "the refined solve did not converge: " +
                                fine.report.status_text}};
    json joints = json::object();
    const auto final_joints = [](const FemOutcome &outcome) {
      return outcome.result.increments.empty() ?
               std::vector<Contact::JointReport>() :
               outcome.result.increments.back().joints;
    };
    const auto coarse_joints = final_joints(coarse);
    const auto fine_joints   = final_joints(fine);
    using Member = double Contact::JointReport::*;
    const std::pair<const char *, Member> figures[] = {
      {"normal_force_N_per_m", &Contact::JointReport::normal_force},
      {"contact_length_m", &Contact::JointReport::closed_length},
      {"sigma_max_Pa", &Contact::JointReport::peak_normal_stress},
      {"sigma_max_averaged_Pa",
       &Contact::JointReport::averaged_peak_normal_stress}};
    for (std::size_t k = 0; k < coarse_joints.size() && k < fine_joints.size();
         ++k)
      {
        json quantities = json::object();
        for (const auto &[key, member] : figures)
          {
            const double coarse_value = coarse_joints[k].*member;
            const double fine_value   = fine_joints[k].*member;
            const double difference   = std::abs(coarse_value - fine_value);
            quantities[key] = {
              {"value", coarse_value},
              {"refined_value", fine_value},
              {"absolute_error", difference},
              {"relative_error",
               fine_value != 0. ? json(difference / std::abs(fine_value)) :
                                  json(nullptr)}};
          }
        joints[coarse_joints[k].name] = quantities;
      }
    return {{"method", method},
            {"status", "available"},
            {"refined_n_dofs", fine.result.n_dofs},
            {"refined_status", fine.report.status},
            {"joints", joints}};
  }
} // namespace FloorBlock::Pipeline
