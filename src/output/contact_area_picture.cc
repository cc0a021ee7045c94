#include <contact/joint_law.h>
#include <output/contact_area_picture.h>
#include <output/gnuplot.h>

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

namespace FloorBlock::Output
{
  namespace
  {
    /** The patch of joint surface one node pair stands for. */
    struct Patch
    {
      double z, z_from, z_to;  ///< m, along the face: the section and its share
      double arc_from, arc_to; ///< m, along the joint
      const Contact::JointNodeSample *sample;
    };

    /**
     * Every node pair's patch: along the joint from the midpoint to the
     * previous pair to the midpoint to the next (the first and last pairs
     * end at their own position), along the face the section's share.
     */
    void
    for_each_patch(const Contact::JointReport               &joint,
                   const std::function<void(const Patch &)> &visit)
    {
      for (const Contact::JointSection &section : joint.along_face)
        {
          const auto &profile = section.profile;
          for (std::size_t k = 0; k < profile.size(); ++k)
            {
              const double here = profile[k].arc_position;
              const double from =
                k == 0 ? here : (profile[k - 1].arc_position + here) / 2.;
              const double to = k + 1 == profile.size() ?
                                  here :
                                  (here + profile[k + 1].arc_position) / 2.;
              visit({section.z,
                     section.z_from,
                     section.z_to,
                     from,
                     to,
                     &profile[k]});
            }
        }
    }
  } // namespace

  std::string
  contact_area_csv(const Contact::JointReport &joint)
  {
    std::string csv = fmt::format(
      "# Joint {}: one row per node pair of every cross-section along the "
      "face; the pair stands for z_from_m..z_to_m along the face and "
      "arc_from_m..arc_to_m along the joint; normal traction > 0 in "
      "compression.\n"
      "z_m,z_from_m,z_to_m,arc_position_m,arc_from_m,arc_to_m,x_m,y_m,"
      "gap_m,normal_traction_Pa,state\n",
      joint.name);
    for_each_patch(joint, [&](const Patch &patch) {
      const auto &sample = *patch.sample;
      csv += fmt::format("{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},"
                         "{:.9e},{:.9e},{:.9e},{}\n",
                         patch.z,
                         patch.z_from,
                         patch.z_to,
                         sample.arc_position,
                         patch.arc_from,
                         patch.arc_to,
                         sample.position[0],
                         sample.position[1],
                         sample.gap,
                         sample.normal_traction,
                         Contact::state_name(sample.state));
    });
    return csv;
  }

  void
  write_contact_area_picture(const Contact::JointReport &joint,
                             const std::string          &png_path)
  {
    if (joint.along_face.empty())
      return;
    // gnuplot boxxyerror rows: centre, half extents' ends, colour (MPa).
    std::string closed_patches;
    double      lowest    = std::numeric_limits<double>::infinity();
    double      highest   = -std::numeric_limits<double>::infinity();
    double      joint_end = 0.;
    for_each_patch(joint, [&](const Patch &patch) {
      joint_end = std::max(joint_end, patch.arc_to);
      if (patch.sample->state == Contact::JointState::open)
        return;
      lowest  = std::min(lowest, patch.arc_from);
      highest = std::max(highest, patch.arc_to);
      closed_patches +=
        fmt::format("{:.6e} {:.6e} {:.6e} {:.6e} {:.6e} {:.6e} {:.6e}\n",
                    (patch.z_from + patch.z_to) / 2.,
                    patch.sample->arc_position,
                    patch.z_from,
                    patch.z_to,
                    patch.arc_from,
                    patch.arc_to,
                    patch.sample->normal_traction / 1e6);
    });
    const double face_length = joint.along_face.back().z_to;
    // The closed zone with a quarter of its extent on either side; the
    // whole joint when nothing is closed.
    const double margin =
      closed_patches.empty() ? 0. : 0.25 * (highest - lowest);
    const double from =
      closed_patches.empty() ? 0. : std::max(0., lowest - margin);
    const double to = closed_patches.empty() ?
                        joint_end :
                        std::min(joint_end, highest + margin);
    render_png(
      fmt::format(
        "set title \"Joint {}: contact area {:.4g} m^2 over {:.4g} m of face "
        "(area / face length {:.1f} mm), peak {:.3g} MPa\"\n"
        "set xlabel 'distance along the face z (m)'\n"
        "set ylabel 'distance along the joint from its first node (m)'\n"
        "set cblabel 'normal traction (MPa)'\n"
        "set xrange [0:{:.6e}]\nset yrange [{:.6e}:{:.6e}]\n"
        "set palette rgb 33,13,10\nset style fill solid 1.0 noborder\n"
        "set grid front\n"
        "plot '-' using 1:2:3:4:5:6:7 with boxxyerror fc palette "
        "title 'closed node pairs (blank: open)'\n{}e\n",
        joint.name,
        joint.closed_length * face_length,
        face_length,
        1e3 * joint.closed_length,
        joint.peak_normal_stress / 1e6,
        face_length,
        from,
        to,
        closed_patches.empty() ? "NaN NaN NaN NaN NaN NaN NaN\n" :
                                 closed_patches),
      png_path,
      1000,
      600);
  }
} // namespace FloorBlock::Output
