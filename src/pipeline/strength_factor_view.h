#pragma once

#include <contact/contact_solver.h>
#include <parameters/scenario_parameters.h>

#include <string>

namespace FloorBlock::Pipeline
{
  /**
   * @brief strength_factor.png: the Hoek-Brown strength factor of the
   * solver's last converged stress around the face block's floor-level
   * corner (Safety::strength_factor_map(), ten critical distances either
   * side and below), with the contour FS = 1 and the corner's path.
   * Writes nothing when no increment converged or the scene has no
   * vertical joint.
   */
  void
  write_strength_factor_view(const Parameters::ScenarioParameters &scene,
                             const Contact::ContactSolver<2>      &solver,
                             const Fem::ElasticModel<2>           &model,
                             const std::string                    &png_path);
} // namespace FloorBlock::Pipeline
