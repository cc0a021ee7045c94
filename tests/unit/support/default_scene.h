#pragma once

// params/default.prm read as a user's scene, with optional overrides
// ("Subsection/Entry=value"), for tests of what is derived from a scene.
#include <parameters/scenario_parameters.h>

#include <string>
#include <vector>

namespace FloorBlock::Testing
{
  inline Parameters::ScenarioParameters
  default_scene(const std::vector<std::string> &overrides = {})
  {
    return Parameters::read_scenario(std::string(FLOORBLOCK_SOURCE_DIR) +
                                       "/params/default.prm",
                                     overrides);
  }
} // namespace FloorBlock::Testing
