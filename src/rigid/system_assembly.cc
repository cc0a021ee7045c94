#include <rigid/system_assembly.h>

#include <algorithm>
#include <array>

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    constexpr unsigned int dofs_per_block = 3;

    /** One side of a point: its first row and its displacement derivatives. */
    struct SideTerms
    {
      bool                                movable   = false;
      unsigned int                        first_row = 0;
      std::array<dealii::Tensor<1, 2>, 3> derivatives;
      /** +1 for side B, -1 for side A: the sign of its part of the jump. */
      double sign = 1.;
    };

    SideTerms
    side_terms(const BodyRef                       &body,
               const double                         sign,
               const dealii::Point<2>              &point,
               const std::vector<dealii::Point<2>> &centroids)
    {
      SideTerms terms;
      terms.sign = sign;
      if (body.kind != BodyKind::block)
        return terms;
      terms.movable   = true;
      terms.first_row = dofs_per_block * body.index;
      terms.derivatives =
        displacement_derivatives(centroids[body.index], point);
      return terms;
    }
  } // namespace

  void
  assemble_system(const JointSet                &joint_set,
                  const JointResponses          &responses,
                  const std::vector<BlockLoads> &loads,
                  const double                   gravity_factor,
                  const double                   support_factor,
                  const AssemblyTargets         &targets)
  {
    const unsigned int n_rows = dofs_per_block * joint_set.n_blocks();
    if (targets.residual != nullptr)
      targets.residual->assign(n_rows, 0.);
    if (targets.tangent != nullptr)
      {
        if (targets.tangent->size != n_rows)
          *targets.tangent = DenseMatrix(n_rows);
        targets.tangent->clear_values();
      }

    const std::vector<JointGeometry> &joints = joint_set.joints();
    for (unsigned int j = 0; j < joints.size(); ++j)
      for (unsigned int p = 0; p < joints[j].points.size(); ++p)
        {
          const JointPoint                &point    = joints[j].points[p];
          const Contact::JointResponse<2> &response = responses[j][p];
          if (response.state == Contact::JointState::open)
            continue;
          dealii::Tensor<2, 2> point_tangent = response.tangent;
          if (targets.slip_stabilisation > 0. &&
              response.state == Contact::JointState::slip)
            point_tangent +=
              targets.slip_stabilisation *
              joint_set.law(joints[j]).parameters().shear_stiffness *
              dealii::outer_product(point.tangent, point.tangent);
          const std::array<SideTerms, 2> sides = {
            {side_terms(
               joints[j].side_a, -1., point.position, joint_set.centroids()),
             side_terms(
               joints[j].side_b, 1., point.position, joint_set.centroids())}};
          for (const SideTerms &row_side : sides)
            {
              if (!row_side.movable)
                continue;
              for (unsigned int r = 0; r < dofs_per_block; ++r)
                {
                  const dealii::Tensor<1, 2> &row_derivative =
                    row_side.derivatives[r];
                  if (targets.residual != nullptr)
                    (*targets.residual)[row_side.first_row + r] +=
                      row_side.sign * point.weight *
                      (row_derivative * response.force_density);
                  if (targets.tangent == nullptr)
                    continue;
                  // d(row force)/d(jump), then chain rule through the jump.
                  const dealii::Tensor<1, 2> row_tangent =
                    row_side.sign * point.weight *
                    (row_derivative * point_tangent);
                  for (const SideTerms &column_side : sides)
                    {
                      if (!column_side.movable)
                        continue;
                      for (unsigned int c = 0; c < dofs_per_block; ++c)
                        (*targets.tangent)(row_side.first_row + r,
                                           column_side.first_row + c) +=
                          column_side.sign *
                          (row_tangent * column_side.derivatives[c]);
                    }
                }
            }
        }

    if (targets.residual == nullptr)
      return;
    for (unsigned int index = 0; index < loads.size(); ++index)
      {
        const std::array<double, 3> applied =
          applied_force(loads[index], gravity_factor, support_factor);
        for (unsigned int r = 0; r < dofs_per_block; ++r)
          (*targets.residual)[dofs_per_block * index + r] -= applied[r];
      }
  }
} // namespace FloorBlock::RigidBlocks
