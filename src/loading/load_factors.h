#pragma once

#include <loading/load_stage.h>

namespace FloorBlock::Loading
{
  /**
   * @brief Fractions of the full loads applied in one load state (-):
   * gravity, the support loads, and the prescribed floor uplift.
   */
  struct LoadFactors
  {
    double gravity = 0.;
    double support = 0.;
    double uplift  = 0.;
  };

  /**
   * @brief The factors at fraction @p stage_factor of @p stage, with every
   * earlier stage complete (so a skipped gravity stage means gravity enters
   * at full factor with the first support-load increment).
   * @param[in] gravity_with_support Gravity rises with the support load in
   *   the support stage (LoadSteps::gravity_with_pressure).
   */
  LoadFactors
  stage_factors(const LoadStage stage,
                const double    stage_factor,
                const bool      gravity_with_support);
} // namespace FloorBlock::Loading
