#pragma once

#include <geometry/assembly_description.h>
#include <parameters/scenario_parameters.h>

namespace FloorBlock::Scene
{
  /** @brief The Gmsh block assembly of a scene (geometry and mesh sizes). */
  Geometry::AssemblyDescription
  assembly_description(const Parameters::ScenarioParameters &scene);
} // namespace FloorBlock::Scene
