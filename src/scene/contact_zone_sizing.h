#pragma once

#include <geometry/local_size_field.h>
#include <parameters/scenario_parameters.h>

#include <optional>
#include <vector>

namespace FloorBlock::Scene
{
  /**
   * How far along a vertical joint, from each end, the contact-zone cells
   * reach, in estimated contact lengths c. More than 1 because Eq. 6.51 is
   * an estimate: on the default scene c = 459 mm against 348 mm computed
   * (+32 %); 1.5 also covers an estimate a third too short.
   */
  constexpr double contact_zone_reach = 1.5;

  /**
   * @brief The closed-form contact length of the face joint (m), Eq. 6.51:
   * the shortest of the mechanisms whose corner contact has a length
   * (status ok, or longer than the block, then capped at the block
   * height); empty when none has one.
   */
  std::optional<double>
  estimated_contact_length(const Parameters::ScenarioParameters &scene);

  /**
   * @brief Size requests that put the ends of the contact zones in cells
   * sized from the scene: along both ends of every vertical joint, over
   * contact_zone_reach c from the end, points a cell apart asking for
   * cells of c / Mesh/Cells per contact length (not below Mesh/Corner
   * size); beyond them the sizes grow at Mesh/Growth rate. Empty when the
   * parameter is 0 or estimated_contact_length() has no answer.
   *
   * Why: the compliant joints' contact zone ends where the relative
   * rotation of the blocks closes the gap, and the corner grading alone
   * leaves that end in cells of 0.02 + 0.3 d m (12 cm at the default face
   * joint's 0.35 m). Measured on the default scene: face contact length
   * 341.2 mm on the graded mesh, 345.0 mm with 6 cm cells over the face
   * joint's upper 0.5 m, against 347.8 mm converged, at 3 % more DoFs.
   * The face joint's estimate serves every vertical joint: it carries the
   * largest force, so its zone is the shortest, and longer zones are then
   * over-resolved, never under-resolved.
   */
  std::vector<Geometry::LocalSize>
  contact_zone_sizes(const Parameters::ScenarioParameters &scene);
} // namespace FloorBlock::Scene
