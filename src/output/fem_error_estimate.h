#pragma once

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>

namespace FloorBlock::Output
{
  /** One FEM figure against the same figure of a refined solve. */
  struct FigureError
  {
    double value          = 0.; ///< the solve's figure (SI unit of the figure)
    double refined_value  = 0.; ///< the refined solve's figure
    /**
     * Estimated error of value: Pipeline::error_from_refined_difference
     * times |value - refined_value|.
     */
    double absolute_error = 0.;
    /** absolute_error / |refined_value|; none when refined_value is 0. */
    std::optional<double> relative_error;
  };

  /** The estimated errors of one joint's figures. */
  struct JointErrors
  {
    FigureError normal_force;       ///< N/m
    FigureError contact_length;     ///< m
    FigureError sigma_max;          ///< Pa, pointwise peak normal stress
    FigureError sigma_max_averaged; ///< Pa, averaged over the averaging length
  };

  /**
   * The discretisation error of each FEM figure, estimated from the
   * difference to one refined solve (summary.json's fem_error_estimate).
   */
  struct FemErrorEstimate
  {
    std::string  method;            ///< how the refined solve was refined
    bool         available = false; ///< false: the refined solve failed
    std::string  status_text;       ///< why not available (else empty)
    unsigned int refined_n_dofs = 0;
    std::string  refined_status;
    /** By joint name ("vertical 6"), as in fem.json. */
    std::map<std::string, JointErrors> joints;
  };

  /**
   * @brief summary.json's fem_error_estimate: method and status; when
   * available the refined DoFs and status and, per joint and figure (keys
   * of fem.json: normal_force_N_per_m, contact_length_m, sigma_max_Pa,
   * sigma_max_averaged_Pa), value, refined_value, absolute_error and
   * relative_error (null where the refined value is 0).
   */
  nlohmann::json
  fem_error_estimate_json(const FemErrorEstimate &estimate);
} // namespace FloorBlock::Output
