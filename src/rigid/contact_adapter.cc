#include <geometry/ids.h>
#include <rigid/contact_adapter.h>

#include <postprocess/joint_report.h>

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    /** Unknowns of a rigid block: centroid translation x, y and rotation. */
    constexpr unsigned int n_dofs_per_block = 3;

    /**
     * Factor from the rigid model's shear sign to the FEM's (see
     * to_contact_result()): +1 on vertical joints, -1 on the bedding.
     */
    double
    shear_sign(const JointKind kind)
    {
      return kind == JointKind::vertical ? 1. : -1.;
    }

    Contact::JointReport
    contact_joint(const RigidJointReport &joint,
                  const JointGeometry    &geometry,
                  const double            averaging_length)
    {
      Contact::JointReport report;
      report.name               = joint.name;
      report.normal_force       = joint.normal_force;
      report.shear_force        = shear_sign(joint.kind) * joint.shear_force;
      report.closed_length      = joint.contact_length;
      report.mean_normal_stress = joint.mean_normal_traction;
      report.averaging_length   = averaging_length;
      report.counts             = joint.counts;
      if (joint.profile.size() != geometry.points.size())
        return report;
      std::vector<double> weights;
      for (unsigned int p = 0; p < joint.profile.size(); ++p)
        {
          const ProfilePoint      &point = joint.profile[p];
          Contact::JointNodeSample sample;
          // Rigid coordinates increase along the joint (layout order), as
          // add_peak_stresses() needs.
          sample.arc_position    = point.coordinate;
          sample.position        = point.position;
          sample.normal_traction = point.normal_traction;
          sample.tangential_traction =
            shear_sign(joint.kind) * point.shear_traction;
          sample.gap   = point.gap;
          sample.state = point.state;
          report.profile.push_back(sample);
          weights.push_back(geometry.points[p].weight);
        }
      Postprocess::add_peak_stresses(report, weights);
      return report;
    }

    bool
    is_block(const BodyRef &body)
    {
      return body.kind == BodyKind::block;
    }

    /** Applied loads and the fixed bodies' contact forces on the blocks. */
    Contact::ForceBalance
    force_balance(const IncrementReport &increment, const Model &model)
    {
      Contact::ForceBalance balance;
      for (const BlockLoads &loads : model.loads())
        {
          const auto force = applied_force(loads,
                                           increment.gravity_factor,
                                           increment.support_factor);
          balance.applied_load[0] += force[0];
          balance.applied_load[1] += force[1];
        }
      const auto &geometry = model.joint_set().joints();
      for (unsigned int j = 0; j < geometry.size(); ++j)
        {
          const bool a_is_block = is_block(geometry[j].side_a);
          const bool b_is_block = is_block(geometry[j].side_b);
          // force_on_side_b acts on B; A receives its opposite.
          const auto &force = increment.joints[j].force_on_side_b;
          for (unsigned int c = 0; c < 2; ++c)
            if (b_is_block && !a_is_block)
              balance.support_reaction[c] += force[c];
            else if (a_is_block && !b_is_block)
              balance.support_reaction[c] -= force[c];
        }
      balance.relative_imbalance = increment.relative_imbalance;
      return balance;
    }

    double
    stage_factor(const IncrementReport &increment)
    {
      switch (increment.stage)
        {
          case Loading::LoadStage::gravity:
            return increment.gravity_factor;
          case Loading::LoadStage::support_pressure:
            return increment.support_factor;
          case Loading::LoadStage::uplift:
            return increment.uplift_factor;
        }
      return 0.;
    }

    Contact::IncrementResult
    contact_increment(const IncrementReport &increment,
                      const Model           &model,
                      const double           averaging_length)
    {
      Contact::IncrementResult result;
      result.stage               = increment.stage;
      result.stage_factor        = stage_factor(increment);
      result.n_newton_iterations = increment.n_iterations;
      result.n_cutbacks          = increment.n_cutbacks;
      result.relative_residual   = increment.relative_residual;
      result.counts              = increment.counts;
      result.balance             = force_balance(increment, model);
      result.wall_time           = increment.wall_time;
      const auto &geometry       = model.joint_set().joints();
      for (unsigned int j = 0; j < increment.joints.size(); ++j)
        result.joints.push_back(
          contact_joint(increment.joints[j], geometry[j], averaging_length));
      for (unsigned int i = 1; i <= increment.motions.size(); ++i)
        {
          Fem::RigidMotion<2> motion;
          motion.translation = increment.motions[i - 1].translation;
          motion.rotation    = increment.motions[i - 1].rotation;
          result.motions[Geometry::Ids::block_material(i)] = motion;
        }
      result.motions[Geometry::Ids::face_block_material] =
        Fem::RigidMotion<2>();
      return result;
    }
  } // namespace

  Contact::SolveResult
  to_contact_result(const RigidSolveResult &rigid,
                    const Model            &model,
                    const double            averaging_length)
  {
    Contact::SolveResult result;
    for (const IncrementReport &increment : rigid.increments)
      result.increments.push_back(
        contact_increment(increment, model, averaging_length));
    result.wall_times["Rigid blocks: solve"] = rigid.wall_time;
    result.n_dofs          = n_dofs_per_block * model.joint_set().n_blocks();
    result.n_contact_pairs = 0;
    return result;
  }
} // namespace FloorBlock::RigidBlocks
