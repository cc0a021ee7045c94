#include <loading/load_factors.h>

namespace FloorBlock::Loading
{
  LoadFactors
  stage_factors(const LoadStage stage,
                const double    stage_factor,
                const bool      gravity_with_support)
  {
    switch (stage)
      {
        case LoadStage::gravity:
          return {stage_factor, 0., 0.};
        case LoadStage::support_pressure:
          return {gravity_with_support ? stage_factor : 1., stage_factor, 0.};
        case LoadStage::uplift:
          return {1., 1., stage_factor};
      }
    return {};
  }
} // namespace FloorBlock::Loading
