#include <contact/uplift.h>
#include <rigid/joint_set.h>

namespace FloorBlock::RigidBlocks
{
  JointSet::JointSet(const ModelDescription &description)
    : joint_list(build_joints(description.assembly,
                              description.solver.n_points_per_joint))
    , uplift(description.uplift)
    , bedding_law(description.bedding_joint)
    , vertical_law(description.vertical_joint)
  {
    for (unsigned int index = 0; index < description.assembly.n_blocks; ++index)
      block_centroids.push_back(block_centroid(description.assembly, index));
  }

  const std::vector<JointGeometry> &
  JointSet::joints() const
  {
    return joint_list;
  }

  const std::vector<dealii::Point<2>> &
  JointSet::centroids() const
  {
    return block_centroids;
  }

  unsigned int
  JointSet::n_blocks() const
  {
    return block_centroids.size();
  }

  const Contact::CoulombJoint<2> &
  JointSet::law(const JointGeometry &joint) const
  {
    return joint.kind == JointKind::bedding ? bedding_law : vertical_law;
  }

  dealii::Tensor<1, 2>
  JointSet::side_displacement(const BodyRef                  &body,
                              const dealii::Point<2>         &point,
                              const std::vector<BlockMotion> &motions,
                              const double uplift_factor) const
  {
    switch (body.kind)
      {
        case BodyKind::block:
          return point_displacement(motions[body.index],
                                    block_centroids[body.index],
                                    point);
        case BodyKind::base:
          return Contact::uplift_displacement(uplift, uplift_factor, point);
        case BodyKind::face_block:
          break;
      }
    return dealii::Tensor<1, 2>();
  }

  JointResponses
  JointSet::evaluate(const std::vector<BlockMotion> &motions,
                     const double                    uplift_factor,
                     const JointHistories           &histories) const
  {
    JointResponses responses(joint_list.size());
    for (unsigned int j = 0; j < joint_list.size(); ++j)
      {
        const JointGeometry            &joint     = joint_list[j];
        const Contact::CoulombJoint<2> &joint_law = law(joint);
        responses[j].reserve(joint.points.size());
        for (unsigned int p = 0; p < joint.points.size(); ++p)
          {
            const JointPoint          &point = joint.points[p];
            const dealii::Tensor<1, 2> jump  = side_displacement(joint.side_b,
                                                                point.position,
                                                                motions,
                                                                uplift_factor) -
                                              side_displacement(joint.side_a,
                                                                point.position,
                                                                motions,
                                                                uplift_factor);
            responses[j].push_back(
              joint_law.evaluate(jump, point.normal, histories[j][p]));
          }
      }
    return responses;
  }

  JointHistories
  JointSet::virgin_histories() const
  {
    JointHistories histories(joint_list.size());
    for (unsigned int j = 0; j < joint_list.size(); ++j)
      histories[j].resize(joint_list[j].points.size());
    return histories;
  }

  JointHistories
  committed_histories(const JointHistories &previous,
                      const JointResponses &responses)
  {
    JointHistories histories = previous;
    for (unsigned int j = 0; j < histories.size(); ++j)
      for (unsigned int p = 0; p < histories[j].size(); ++p)
        {
          const Contact::JointResponse<2> &response = responses[j][p];
          Contact::JointHistory<2>        &history  = histories[j][p];
          // Compliant law: the normal spring has no memory.
          history.normal_base     = 0.;
          history.tangential_base = response.tangential_traction;
          history.reference_slip  = response.slip;
          history.intact =
            history.intact && response.state == Contact::JointState::stick;
        }
    return histories;
  }
} // namespace FloorBlock::RigidBlocks
