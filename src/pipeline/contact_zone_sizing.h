#pragma once

#include <output/result_folder.h>
#include <parameters/scenario_parameters.h>
#include <scene/mesh_sizing.h>

namespace FloorBlock::Pipeline
{
  /**
   * @brief The contact-zone sizes of a scene's mesh: Eq. 6.51's
   * (Scene::closed_form_contact_zones()) where it has an answer; otherwise,
   * for a 2D elastic scene, the zones a first solve computes
   * (Scene::computed_contact_zones()).
   *
   * The first solve is of the scene on its plain Gmsh mesh: no contact-zone
   * sizes, no global refinements, nothing written (its mesh.msh is
   * overwritten by the sized mesh). It depends on the scene alone, so every
   * level of a refinement ladder gets the same sizes and the nested levels
   * stay nested. A 3D scene is not solved first (its cross-section's 2D
   * solve would not be the 3D scene's), and a first solve that does not
   * converge gives no sizes: both say so in ContactZoneSizing::reason.
   */
  Scene::ContactZoneSizing
  contact_zone_sizing(const Parameters::ScenarioParameters &scene,
                      const Output::ResultFolder           &folder);
} // namespace FloorBlock::Pipeline
