#include <contact/active_set.h>
#include <rigid/joint_report.h>

namespace FloorBlock::RigidBlocks
{
  namespace
  {
    /**
     * Shear traction in the chapter's sense (see
     * RigidJointReport::shear_force). The law's tangential traction t_t is the
     * tangential force per length on side A (B receives -t_t). Vertical joint:
     * A is block j, the chapter counts the downward force on it, -t_t.e_y.
     * Bedding: B is the block, the chapter counts the force on it towards the
     * face, i.e. along -tangent: (-t_t).(-tangent).
     */
    double
    chapter_shear(const JointGeometry             &joint,
                  const JointPoint                &point,
                  const Contact::JointResponse<2> &response)
    {
      const double along_tangent = response.tangential_traction * point.tangent;
      return joint.kind == JointKind::vertical ? -along_tangent : along_tangent;
    }

    /** Length of the segment between two points that is in compression. */
    double
    compressed_length(const JointPoint                &first,
                      const JointPoint                &second,
                      const Contact::JointResponse<2> &first_response,
                      const Contact::JointResponse<2> &second_response)
    {
      const double length = (second.position - first.position).norm();
      // Overlap = -gap, linear along a straight segment.
      const double overlap_first  = -first_response.gap;
      const double overlap_second = -second_response.gap;
      const bool   first_in       = first_response.normal_traction > 0.;
      const bool   second_in      = second_response.normal_traction > 0.;
      if (first_in && second_in)
        return length;
      if (!first_in && !second_in)
        return 0.;
      const double inside  = first_in ? overlap_first : overlap_second;
      const double outside = first_in ? overlap_second : overlap_first;
      // The zero of the interpolated overlap; outside <= 0 < inside.
      return inside > outside ? length * inside / (inside - outside) : 0.;
    }

    RigidJointReport
    report_joint(const JointGeometry                          &joint,
                 const std::vector<Contact::JointResponse<2>> &responses,
                 const bool                                    with_profile)
    {
      RigidJointReport report;
      report.name   = joint.name;
      report.kind   = joint.kind;
      report.number = joint.number;
      std::vector<Contact::JointState> states;
      for (unsigned int p = 0; p < joint.points.size(); ++p)
        {
          const JointPoint                &point    = joint.points[p];
          const Contact::JointResponse<2> &response = responses[p];
          const double shear = chapter_shear(joint, point, response);
          report.normal_force += point.weight * response.normal_traction;
          report.shear_force += point.weight * shear;
          // Force density is the internal force on side B; the contact
          // force on B is its negative.
          const dealii::Tensor<1, 2> force =
            -point.weight * response.force_density;
          report.force_on_side_b += force;
          report.moment_on_side_b +=
            point.position[0] * force[1] - point.position[1] * force[0];
          if (response.normal_traction > report.peak_normal_traction)
            {
              report.peak_normal_traction = response.normal_traction;
              report.peak_coordinate      = point.coordinate;
            }
          if (p + 1 < joint.points.size())
            report.contact_length += compressed_length(point,
                                                       joint.points[p + 1],
                                                       response,
                                                       responses[p + 1]);
          states.push_back(response.state);
          if (with_profile)
            report.profile.push_back({point.coordinate,
                                      point.position,
                                      response.normal_traction,
                                      shear,
                                      response.gap,
                                      response.state});
        }
      report.counts = Contact::count_states(states);
      if (report.contact_length > 0.)
        report.mean_normal_traction =
          report.normal_force / report.contact_length;
      return report;
    }
  } // namespace

  std::vector<RigidJointReport>
  make_joint_reports(const JointSet       &joint_set,
                     const JointResponses &responses,
                     const bool            with_profiles)
  {
    std::vector<RigidJointReport> reports;
    for (unsigned int j = 0; j < joint_set.joints().size(); ++j)
      reports.push_back(
        report_joint(joint_set.joints()[j], responses[j], with_profiles));
    return reports;
  }
} // namespace FloorBlock::RigidBlocks
