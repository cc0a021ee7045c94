#include <rigid/block_motion.h>

namespace FloorBlock::RigidBlocks
{
  dealii::Tensor<1, 2>
  point_displacement(const BlockMotion      &motion,
                     const dealii::Point<2> &centroid,
                     const dealii::Point<2> &point)
  {
    const dealii::Tensor<1, 2> arm          = point - centroid;
    dealii::Tensor<1, 2>       displacement = motion.translation;
    displacement[0] -= motion.rotation * arm[1];
    displacement[1] += motion.rotation * arm[0];
    return displacement;
  }

  std::array<dealii::Tensor<1, 2>, 3>
  displacement_derivatives(const dealii::Point<2> &centroid,
                           const dealii::Point<2> &point)
  {
    const dealii::Tensor<1, 2> arm = point - centroid;
    return {{dealii::Tensor<1, 2>({1., 0.}),
             dealii::Tensor<1, 2>({0., 1.}),
             dealii::Tensor<1, 2>({-arm[1], arm[0]})}};
  }
} // namespace FloorBlock::RigidBlocks
