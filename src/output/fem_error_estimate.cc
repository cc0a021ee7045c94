#include <output/fem_error_estimate.h>

#include <utility>

namespace FloorBlock::Output
{
  using nlohmann::json;

  json
  fem_error_estimate_json(const FemErrorEstimate &estimate)
  {
    if (!estimate.available)
      return {{"method", estimate.method},
              {"status", "unavailable"},
              {"status_text", estimate.status_text}};
    const std::pair<const char *, FigureError JointErrors::*> figures[] = {
      {"normal_force_N_per_m", &JointErrors::normal_force},
      {"contact_length_m", &JointErrors::contact_length},
      {"sigma_max_Pa", &JointErrors::sigma_max},
      {"sigma_max_averaged_Pa", &JointErrors::sigma_max_averaged}};
    json joints = json::object();
    for (const auto &[name, errors] : estimate.joints)
      {
        json quantities = json::object();
        for (const auto &[key, member] : figures)
          {
            const FigureError &error = errors.*member;
            quantities[key] = {
              {"value", error.value},
              {"refined_value", error.refined_value},
              {"absolute_error", error.absolute_error},
              {"relative_error", error.relative_error ?
                                   json(*error.relative_error) :
                                   json(nullptr)}};
          }
        joints[name] = quantities;
      }
    return {{"method", estimate.method},
            {"status", "available"},
            {"refined_n_dofs", estimate.refined_n_dofs},
            {"refined_status", estimate.refined_status},
            {"joints", joints}};
  }
} // namespace FloorBlock::Output
