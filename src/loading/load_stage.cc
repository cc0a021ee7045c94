#include <loading/load_stage.h>

namespace FloorBlock::Loading
{
  const char *
  stage_name(const LoadStage stage)
  {
    switch (stage)
      {
        case LoadStage::gravity:
          return "gravity";
        case LoadStage::support_pressure:
          return "support load";
        case LoadStage::uplift:
          return "uplift";
      }
    return "unknown";
  }
} // namespace FloorBlock::Loading
