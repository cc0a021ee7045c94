#include <rigid/motion_predictor.h>

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    /** e_z x v: the displacement per unit rotation of an arm v. */
    dealii::Tensor<1, 2>
    rotated_arm(const dealii::Tensor<1, 2> &arm)
    {
      return dealii::Tensor<1, 2>({-arm[1], arm[0]});
    }
  } // namespace

  std::vector<BlockMotion>
  predict_motions(const JointSet                 &joint_set,
                  const std::vector<BlockMotion> &motions,
                  const double                    previous_uplift,
                  const double                    target_uplift)
  {
    std::vector<BlockMotion> predicted = motions;
    if (target_uplift == previous_uplift)
      return predicted;
    const BodyRef base{BodyKind::base, 0};
    for (const JointGeometry &joint : joint_set.joints())
      {
        if (joint.kind != JointKind::bedding)
          continue;
        const unsigned int      index   = joint.side_b.index;
        const dealii::Point<2> &first   = joint.points.front().position;
        const dealii::Point<2> &last    = joint.points.back().position;
        const auto              step_at = [&](const dealii::Point<2> &point) {
          return joint_set.side_displacement(base,
                                             point,
                                             motions,
                                             target_uplift) -
                 joint_set.side_displacement(base,
                                             point,
                                             motions,
                                             previous_uplift);
        };
        const dealii::Tensor<1, 2> step_first = step_at(first);
        const dealii::Tensor<1, 2> step_last  = step_at(last);
        const dealii::Tensor<1, 2> chord      = last - first;
        // Rigid fit through both end points: the rotation from the
        // relative displacement across the chord, the translation from the
        // mean, moved to the centroid.
        const double rotation =
          (step_last - step_first) * rotated_arm(chord) / chord.norm_square();
        const dealii::Point<2> middle = first + chord / 2.;
        predicted[index].translation +=
          (step_first + step_last) / 2. +
          rotation * rotated_arm(joint_set.centroids()[index] - middle);
        predicted[index].rotation += rotation;
      }
    return predicted;
  }
} // namespace FloorBlock::RigidBlocks
