#pragma once

#include <parameters/scenario_parameters.h>

namespace FloorBlock::Scene
{
  /** Most halvings "auto" asks for (64 times the cells). */
  constexpr unsigned int max_auto_global_refinements = 3;

  /**
   * @brief Joint compliance length E/kn (m): the length of rock whose
   * elastic compliance equals the joint's. 0 for the rigid law.
   */
  double
  joint_compliance_length(const Parameters::ScenarioParameters &scene);

  /**
   * @brief How many times the Gmsh mesh of @p scene is refined globally:
   * Mesh/Global refinements, or for "auto" the rule below.
   *
   * Why a rule depends on the joint law: where the joints are compliant
   * (E/kn at least the corner rounding radius r; the default scene:
   * 1.8 m against 1 cm) the springs spread the corner force over their
   * compliance length and the fillet does not matter. With exact contact
   * the fillet alone limits the concentration: the face joint's pressure
   * peaks 0.1-0.5 mm into the 1 cm fillet, and while the corner cells are
   * larger than r the fillet's compliance, hence the blocks' relative
   * rotation and the whole contact zone, moves with every refinement.
   * Measured on the default scene with the rigid law (nested ladder from
   * the 2 cm corner mesh): face contact length +23 %, +3.7 %, +0.12 % at
   * 30 deg, +28 %, -5.0 %, +0.43 % at 10 deg, +4.7 %, +5.4 %, +0.13 % at
   * 45 deg -- it settles once the corner cells are at most r. So "auto"
   * halves until Mesh/Corner size <= r in that case, and never for sharp
   * corners (no length to resolve); at most max_auto_global_refinements
   * times, since each halves every cell of the scene: a fillet much
   * smaller than the corner size asks for a smaller Mesh/Corner size,
   * which refines the corners only.
   */
  unsigned int
  global_refinements(const Parameters::ScenarioParameters &scene);
} // namespace FloorBlock::Scene
