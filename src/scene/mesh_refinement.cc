#include <scene/mesh_refinement.h>

#include <cmath>

namespace FloorBlock::Scene
{
  double
  joint_compliance_length(const Parameters::ScenarioParameters &scene)
  {
    if (scene.joints.law == Contact::JointLawKind::rigid)
      return 0.;
    return scene.material.youngs_modulus() / scene.joints.normal_stiffness;
  }

  unsigned int
  global_refinements(const Parameters::ScenarioParameters &scene)
  {
    if (scene.mesh.global_refinements)
      return *scene.mesh.global_refinements;
    const double radius = scene.geometry.corner_rounding_radius;
    if (radius <= 0. || joint_compliance_length(scene) >= radius)
      return 0;
    unsigned int n_halvings = 0;
    // 1e-9 relative: a corner size of exactly 2 r takes one halving.
    while (n_halvings < max_auto_global_refinements &&
           scene.mesh.corner_size * std::exp2(-double(n_halvings)) >
             radius * (1. + 1e-9))
      ++n_halvings;
    return n_halvings;
  }
} // namespace FloorBlock::Scene
