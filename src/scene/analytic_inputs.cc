#include <analytic/floor_shape.h>
#include <scene/analytic_inputs.h>

#include <algorithm>

namespace FloorBlock::Scene
{
  Analytic::BlockChain
  block_chain(const Parameters::ScenarioParameters &scene)
  {
    const auto  &geometry     = scene.geometry;
    const double block_weight = scene.material.density * scene.loading.gravity *
                                geometry.block_width * geometry.block_height;

    const std::vector<unsigned int> loaded = scene.loaded_blocks();
    const double                    load_per_loaded_block =
      loaded.empty() ?
                           0.0 :
                           scene.loading.support_load / (loaded.size() * geometry.support_width);

    Analytic::BlockChain chain =
      Analytic::uniform_chain(geometry.n_blocks,
                              block_weight,
                              0.0,
                              scene.bedding.inclination,
                              geometry.block_width,
                              geometry.block_height,
                              scene.joints.bedding_friction_angle,
                              scene.joints.vertical_friction_angle);

    for (const unsigned int block : loaded)
      chain.support_load[block - 1] = load_per_loaded_block;

    if (scene.bedding.shape == Geometry::BeddingShape::parabolic)
      chain.inclination =
        Analytic::parabolic_inclinations(geometry.n_blocks,
                                         geometry.block_width,
                                         scene.bedding.curvature);
    for (double &alpha : chain.inclination)
      alpha = true_inclination(alpha, scene.bedding.frame_dip);
    return chain;
  }

  double
  true_inclination(const double frame_inclination, const double frame_dip)
  {
    return frame_inclination - frame_dip;
  }

  double
  face_joint_floor_lift(const Parameters::ScenarioParameters &scene,
                        const Analytic::BlockChain           &chain)
  {
    // The face block is fixed upright in the frame: level in the frame, so
    // -dip against the true horizontal like a level bed. The relative
    // rotation, hence y, is the frame's and does not depend on the dip.
    return Analytic::joint_floor_lift(chain.inclination.back(),
                                      true_inclination(0.,
                                                       scene.bedding.frame_dip),
                                      scene.geometry.block_width);
  }
} // namespace FloorBlock::Scene
