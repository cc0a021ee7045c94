#include <pipeline/convergence_ladder.h>
#include <pipeline/error_estimate.h>

#include <cmath>

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
      coarse.fem["model"] == "rigid blocks" ?
        "difference to one solve with twice the points per joint" :
        "difference to a solve on the next uniform refinement level "
        "(all mesh sizes and the growth rate's excess over 1 halved)";
    // A refined solve that stopped early describes a different load state:
    // comparing with it would be no error estimate at all.
    if (!fine.converged)
      return {{"method", method},
              {"status", "unavailable"},
              {"status_text", "the refined solve did not converge: " +
                                fine.fem["status_text"].get<std::string>()}};
    json joints = json::object();
    const auto &coarse_joints = coarse.fem["joints"];
    const auto &fine_joints   = fine.fem["joints"];
    for (std::size_t k = 0; k < coarse_joints.size() && k < fine_joints.size();
         ++k)
      {
        json quantities = json::object();
        for (const char *key :
             {"normal_force_N_per_m", "contact_length_m", "sigma_max_Pa",
              "sigma_max_averaged_Pa"})
          {
            const double coarse_value = coarse_joints[k][key].get<double>();
            const double fine_value   = fine_joints[k][key].get<double>();
            const double difference   = std::abs(coarse_value - fine_value);
            quantities[key] = {
              {"value", coarse_value},
              {"refined_value", fine_value},
              {"absolute_error", difference},
              {"relative_error",
               fine_value != 0. ? json(difference / std::abs(fine_value)) :
                                  json(nullptr)}};
          }
        joints[coarse_joints[k]["name"].get<std::string>()] = quantities;
      }
    return {{"method", method},
            {"status", "available"},
            {"refined_n_dofs", fine.result.n_dofs},
            {"refined_status", fine.fem["status"]},
            {"joints", joints}};
  }
} // namespace FloorBlock::Pipeline
