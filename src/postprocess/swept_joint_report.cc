#include <contact/swept_sections.h>

#include <postprocess/joint_report.h>
#include <postprocess/swept_joint_report.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace FloorBlock::Postprocess
{
  using namespace Contact;

  namespace
  {
    /** Section peaks closer than this (relative) count as equal. */
    constexpr double same_peak_tolerance = 1e-9;

    /** In-plane (x, y) part of a 3D vector. */
    dealii::Tensor<1, 2>
    in_plane(const dealii::Tensor<1, 3> &vector)
    {
      dealii::Tensor<1, 2> result;
      result[0] = vector[0];
      result[1] = vector[1];
      return result;
    }

    /**
     * One line of pairs as a 2D joint: in-plane positions, normals and
     * tractions, the weights per metre of face (divided by @p line_length,
     * the length of face the line stands for).
     */
    JointReport
    line_report(const std::vector<ContactNode<3>>   &nodes,
                const std::vector<JointResponse<3>> &responses,
                const std::vector<unsigned int>     &line,
                const double                         line_length,
                const std::string                   &name,
                const double                         averaging_length)
    {
      std::vector<ContactNode<2>>   plane_nodes;
      std::vector<JointResponse<2>> plane_responses;
      for (const unsigned int p : line)
        {
          const ContactNode<3>   &node     = nodes[p];
          const JointResponse<3> &response = responses[p];
          ContactNode<2>          plane_node;
          plane_node.joint       = 0;
          plane_node.position    = dealii::Point<2>(in_plane(node.position));
          plane_node.weight      = node.weight / line_length;
          plane_node.normal      = in_plane(node.normal);
          plane_node.initial_gap = node.initial_gap;
          JointResponse<2> plane_response;
          plane_response.state           = response.state;
          plane_response.normal_traction = response.normal_traction;
          plane_response.tangential_traction =
            in_plane(response.tangential_traction);
          plane_response.force_density     = in_plane(response.force_density);
          plane_response.closure_stiffness = response.closure_stiffness;
          plane_response.exact_traction    = response.exact_traction;
          plane_response.gap               = response.gap;
          plane_response.slip              = in_plane(response.slip);
          plane_nodes.push_back(plane_node);
          plane_responses.push_back(plane_response);
        }
      return make_joint_reports(plane_nodes,
                                plane_responses,
                                {name},
                                averaging_length)
        .front();
    }

    /** z of a cross-section's pairs (m). */
    double
    section_z(const std::vector<ContactNode<3>> &nodes,
              const std::vector<unsigned int>   &line)
    {
      return nodes[line.front()].position[2];
    }

    /**
     * Section @p k of @p sections with its line's report @p part: the face
     * it stands for runs between the midpoints to its neighbours (the
     * trapezoidal share of the lumped Q1 weights, section_lengths()).
     */
    JointSection
    section_of(const JointReport                            &part,
               const std::vector<std::vector<unsigned int>> &sections,
               const std::vector<ContactNode<3>>            &nodes,
               const unsigned int                            k,
               const double                                  face_length)
    {
      JointSection section;
      section.z = section_z(nodes, sections[k]);
      section.z_from =
        k == 0 ? 0. : (section_z(nodes, sections[k - 1]) + section.z) / 2.;
      section.z_to               = k + 1 == sections.size() ?
                                     face_length :
                                     (section.z + section_z(nodes, sections[k + 1])) / 2.;
      section.normal_force       = part.normal_force;
      section.shear_force        = part.shear_force;
      section.closed_length      = part.closed_length;
      section.peak_normal_stress = part.peak_normal_stress;
      section.profile            = part.profile;
      return section;
    }
  } // namespace

  std::vector<JointReport>
  make_swept_joint_reports(const std::vector<ContactNode<3>>   &nodes,
                           const std::vector<JointResponse<3>> &responses,
                           const std::vector<std::string>      &names,
                           const double averaging_length,
                           const double face_length)
  {
    std::vector<std::vector<unsigned int>> members(names.size());
    for (unsigned int p = 0; p < nodes.size(); ++p)
      members[nodes[p].joint].push_back(p);

    std::vector<JointReport> reports(names.size());
    for (unsigned int j = 0; j < names.size(); ++j)
      {
        JointReport &report     = reports[j];
        report.name             = names[j];
        report.averaging_length = averaging_length;
        report.face_length      = face_length;
        const auto sections =
          sections_along_face(nodes, members[j], face_length);
        const auto   lengths  = section_lengths(nodes, sections, face_length);
        const double middle_z = face_length / 2.;
        double       profile_offset = std::numeric_limits<double>::infinity();
        double       contact_area   = 0.;
        double       uncertainty    = 0.;
        for (unsigned int k = 0; k < sections.size(); ++k)
          {
            const auto  &line        = sections[k];
            const double line_length = lengths[k];
            if (!(line_length > 0.))
              continue;
            const JointReport part = line_report(
              nodes, responses, line, line_length, names[j], averaging_length);
            report.along_face.push_back(
              section_of(part, sections, nodes, k, face_length));
            report.normal_force += line_length * part.normal_force;
            report.shear_force += line_length * part.shear_force;
            contact_area += line_length * part.closed_length;
            uncertainty += line_length * part.closed_length_uncertainty;
            // Sections whose peaks agree to round-off (a plane-strain or
            // uniformly loaded face) keep the first along the face, so that
            // the position does not depend on the order of sums, e.g. over
            // the processes of a distributed solve.
            if (part.peak_normal_stress >
                report.peak_normal_stress * (1. + same_peak_tolerance))
              {
                report.peak_normal_stress = part.peak_normal_stress;
                report.peak_position      = part.peak_position;
                report.peak_position_z    = nodes[line.front()].position[2];
              }
            report.averaged_peak_normal_stress =
              std::max(report.averaged_peak_normal_stress,
                       part.averaged_peak_normal_stress);
            report.counts.n_stick += part.counts.n_stick;
            report.counts.n_slip += part.counts.n_slip;
            report.counts.n_open += part.counts.n_open;
            const double offset =
              std::abs(nodes[line.front()].position[2] - middle_z);
            if (offset < profile_offset)
              {
                profile_offset = offset;
                report.profile = part.profile;
              }
          }
        report.normal_force /= face_length;
        report.shear_force /= face_length;
        report.closed_length             = contact_area / face_length;
        report.closed_length_uncertainty = uncertainty / face_length;
        report.mean_normal_stress =
          report.closed_length > 0. ?
            report.normal_force / report.closed_length :
            0.;
      }
    return reports;
  }
} // namespace FloorBlock::Postprocess
